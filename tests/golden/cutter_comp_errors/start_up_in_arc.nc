(A start-up of cutter compensation in G02: PS0034 on Fanuc)
G21 G90 G17 F100.
G10 L12 P1 R5.
G0 X0 Y0 Z0
G41 D1 G2 X20. Y0 R10.
M30
