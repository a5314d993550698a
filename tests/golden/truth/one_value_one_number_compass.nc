(One value, one number: CompassNC computes in floating point; G31.LCS.X and the)
(report's skips[].position are the latch as it is, 51.7280591, unrounded)
G90 G17 G21
G54 G0 X0 Y0 Z0 F12000
G31 X100 F200
#100 = # <NC.SysVars.G31.LCS.X>
M30
