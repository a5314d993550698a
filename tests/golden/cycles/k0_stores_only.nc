(K0 stores the hole data without drilling; the next block drills with them; a group-01 code ends the cycle)
G21 G90 G17 G54 F100.
G0 X0 Y0 Z10.
G98 G81 X5. Z-2. R1. K0
X6.
G0 X7.
M30
