(Block times: two dwells in a loop of three passes. Each pass runs the 0.25 s dwell then the 0.1 s one, so line 5 has 3 runs and 0.75 s in all, line 6 3 runs and 0.3 s; the first run of line 5 starts at 0, the last of line 6 ends at the cycle time, 1.05 s)
G21 G90 G54
#1 = 0
WHILE [#1 LT 3] DO1
G04 X0.25
G04 X0.1
#1 = #1 + 1
END1
M30
