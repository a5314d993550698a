(G53 positions at rapid traverse in the machine coordinate system whatever the modal motion, one block only; G53 in G91 moves by the increment)
G21 G90 G17 G54 F100.
G10 L2 P1 X10. Y20. Z-30.
G1 X1. Y1. Z1.
G53 X0 Y0
G53 G0 Z0
X1.
G91 G53 X5.
G90
M30
