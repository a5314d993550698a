(G83 Q5 from R1 to Z-12: back to R after each peck, rapid down to d = 0.5 mm, parameter 5115, short of the depth reached)
G21 G90 G17 G54 F150.
G0 X5. Y5. Z20.
G98 G83 Z-12. R1. Q5.
G80
M30
