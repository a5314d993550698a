(A canned cycle with G41 active is refused in words, not run on the programmed path)
G21 G90 G17 F100.
G10 L12 P1 R5.
G0 X0 Y0 Z10.
G41 D1 X10. Y0
G81 X20. Y0 Z-5. R2.
M30
