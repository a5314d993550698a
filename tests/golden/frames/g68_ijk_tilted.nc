(G31 under a tilted 3-D conversion, G68 X0 Y0 Z0 I1. J0 K0 R90.: the)
(program +Y is the work +Z [right-handed about +X], so G31 Y30. moves the)
(machine up Z from Z0; the trigger at machine Z 18 stops it. #5061-#5063)
(read in the unconverted workpiece coordinates, as under the plane)
(rotation [g31_under_g68]: X0 Y0 Z18. Then G1 Y0 returns along -Z: Z0.)
G21 G90 G17 G54
G0 X0 Y0 Z0
G68 X0 Y0 Z0 I1. J0 K0 R90.
G31 Y30. F300.
#101 = #5061
#102 = #5062
#103 = #5063
G1 Y0 F1000.
#104 = #5043
G69
M30
