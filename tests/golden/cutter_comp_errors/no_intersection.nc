(G41 with D1 = 6.5 into a G03 arc of radius 7.071 about X5 Y5: at the inner corner X10 Y0 the offset line Y6.5 and the offset circle of radius 0.571 do not meet: PS0033 on Fanuc)
G21 G90 G17 F100.
G10 L12 P1 R6.5
G0 X0 Y-20. Z0
G41 D1 G1 X0 Y0
X10.
G3 X10. Y10. I-5. J5.
M30
