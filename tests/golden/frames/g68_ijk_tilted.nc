%
(G68 with a rotation vector not along Z is the 3-D coordinate conversion,)
(not simulated: alarm not_simulated, SN9024, at the G68 block, nothing)
(moved by it.)
N1 G21 G90 G17 G54 G0 X0 Y0 Z10.
N2 G68 X0 Y0 Z0 I1. J0 K0 R30.
N3 G1 X20. F100.
N4 M30
%
