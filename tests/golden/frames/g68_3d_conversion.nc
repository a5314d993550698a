%
(The 3-D coordinate conversion G68 X Y Z I J K R, Fanuc B-62764EN "Three-)
(dimensional coordinate conversion": R degrees about the vector I J K)
(through X Y Z, right-handed; a second G68 nests in the frame the first)
(made; G69 ends both. #5041-#5043 stay in the unconverted workpiece)
(coordinates, #5021-#5023 are the machine's: G54 is X10 Y20 Z-100.)
(End points by hand, d = program point - centre:)
(A: 90 about +X through 0: Y turns to +Z, Z to -Y. X10 Y20 Z5 -> work)
(   X10 Y-5 Z20, machine X20 Y15 Z-80.)
(B: 30 about +Y through X10: d = 10 0 0 -> 10 cos30, 0, -10 sin30:)
(   X20 Y5 Z0 -> X18.660254038 Y5 Z-5; G91 X10 is a vector, turned the)
(   same way: + 8.660254038 0 -5 -> X27.320508076 Y5 Z-10.)
(C: 120 about 1 1 1 through X10 Y20 Z30 carries X to Y, Y to Z, Z to X:)
(   d = 1 2 3 -> 3 1 2: X11 Y22 Z33 -> X13 Y21 Z32.)
(D: 90 about Z, then 90 about X' through the same centre [the second)
(   G68 has no X Y Z]: X10 Y20 Z5 -> second: X10 Y-5 Z20 -> first: X5 Y10)
(   Z20. Then X0 alone keeps the program Y20 Z5: -> X0 Y-5 Z20 -> X5 Y0)
(   Z20: a program X move moves work Y. After G69, X0 Y0 from there.)
G21 G90 G17 G94 F500.
G10 L2 P1 X10. Y20. Z-100.
G54 G0 X0 Y0 Z0
N1 G68 X0 Y0 Z0 I1. J0 K0 R90.
N2 G1 X10. Y20. Z5.
#101 = #5041
#102 = #5042
#103 = #5043
#104 = #5021
#105 = #5022
#106 = #5023
N3 G69
N4 G68 X10. Y0 Z0 I0 J1. K0 R30.
N5 G1 X20. Y5. Z0
#111 = #5041
#112 = #5042
#113 = #5043
N6 G91 G1 X10.
G90
#114 = #5041
#115 = #5042
#116 = #5043
N7 G69
N8 G68 X10. Y20. Z30. I1. J1. K1. R120.
N9 G1 X11. Y22. Z33.
#121 = #5041
#122 = #5042
#123 = #5043
N10 G69
N11 G68 X0 Y0 Z0 I0 J0 K1. R90.
N12 G68 I1. J0 K0 R90.
N13 G1 X10. Y20. Z5.
#131 = #5041
#132 = #5042
#133 = #5043
N14 G1 X0
#134 = #5041
#135 = #5042
#136 = #5043
N15 G69
N16 G0 X0 Y0
M30
%
