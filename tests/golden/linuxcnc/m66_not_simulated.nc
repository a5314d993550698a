( M66 waits for an input and sets #5399: not modelled, refused by name )
G21 G90
M62 P0
M66 P0 L3 Q5
#1 = #5399
M2
