(CompassNC: the latch in machine coordinates and converted to the local system)
G90 G17 G21
G54 G0 X0 Y0 Z0 F12000
G31 X100 F200
#100 = # <NC.SysVars.G31.LCS.X>
G1 Y10 F12000
G1 X[#100]
M30
