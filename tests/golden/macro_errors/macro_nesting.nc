(G65 nests 4 levels deep: the fifth call, alarm 77)
G65 P8200 A1.
M30
O8200
#100=#100+1
G65 P8200
M99
