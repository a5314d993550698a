(G68 I J K under scaling G51: the conversion combined with scaling or)
(mirror image is not simulated, SN9024, at the G68 word.)
G21 G90 G17 G54 G0 X0 Y0 Z10.
G51 X0 Y0 Z0 P2000
G68 X0 Y0 Z0 I1. J0 K0 R30.
G1 X20. F100.
M30
