(A third G68 in the 3-D conversion mode: the manual speaks of the)
(coordinate system rotated twice; skipnc raises the format alarm 5044 at)
(the third; the first two are accepted, nothing moved.)
G21 G90 G17 G54 G0 X0 Y0 Z10.
G68 X0 Y0 Z0 I0 J0 K1. R90.
G68 I1. J0 K0 R90.
G68 I0 J1. K0 R90.
G1 X20. F100.
M30
