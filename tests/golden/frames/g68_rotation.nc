(G68 X10 Y10 R90: program points turn 90 degrees about X10 Y10; a G91 move turns too; G69 cancels)
G21 G90 G17 G54 F100.
G0 X0 Y0 Z5.
G68 X10. Y10. R90.
G0 X20. Y10.
G1 X30.
G91 G1 Y5.
G90 G69 G0 X0 Y0
M30
