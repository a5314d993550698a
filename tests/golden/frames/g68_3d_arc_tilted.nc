(An arc under a 3-D conversion not about Z lies in a tilted plane: not)
(simulated, SN9024, at the G02 block. Along Z it runs [g68_ijk_along_z].)
G21 G90 G17 G54 G0 X0 Y0 Z10.
G68 X0 Y0 Z0 I1. J0 K0 R30.
G1 X10. F100.
G2 X20. Y0 R5.
M30
