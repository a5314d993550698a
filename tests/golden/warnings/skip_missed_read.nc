(A G31 that reaches its end point without a signal stores that end point in #5061..: reading it as a touch is worth a warning, once per miss)
G21 G90 G54
G0 X0 Y0 Z0
G31 Z-5. F100.
#100 = #5063
#101 = #5063
M30
