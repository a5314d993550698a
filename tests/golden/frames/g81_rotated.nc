(G81 in a frame turned by G68 X0 Y0 R90: the holes X10 and X20 on the program's X axis are drilled on the machine's Y axis)
G21 G90 G17 G54 F100.
G0 X0 Y0 Z10.
G68 X0 Y0 R90.
G99 G81 X10. Y0 Z-3. R1.
X20.
G80 G69
M30
