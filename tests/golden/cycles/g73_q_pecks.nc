(G73 Q3 from R2 to Z-7: after each peck a rapid retraction of d = 1 mm, parameter 5114 in the machine file)
G21 G90 G17 G54 F150.
G0 X0 Y0 Z10.
G99 G73 Z-7. R2. Q3.
G80
M30
