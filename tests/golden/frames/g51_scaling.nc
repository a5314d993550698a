(G51 X10 Y10 Z0 P500: half size about X10 Y10 Z0, P without decimal point in 0.001; G50 cancels)
G21 G90 G17 G54 F100.
G0 X0 Y0 Z10.
G51 X10. Y10. Z0 P500
G1 X30. Y10.
G1 Z-4.
G50
G0 X0 Y0 Z10.
M30
