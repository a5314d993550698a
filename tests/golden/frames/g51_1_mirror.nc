(G51.1 X50: X is mirrored about X50, an arc turns the other way; G50.1 X0 cancels)
G21 G90 G17 G54 F100.
G0 X0 Y0 Z5.
G51.1 X50.
G0 X60. Y10.
G1 X70. Y20.
G2 X80. Y10. I10. J0
G50.1 X0
G0 X0 Y0
M30
