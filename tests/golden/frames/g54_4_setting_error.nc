%
(G54.4 Pn, the workpiece setting error compensation [Fanuc A-79634E]: the)
(errors of set n, #26000 + 10 n + 0..5 = dx dy dz da db dc, plus those of)
(No. 00 [#26000-#26005], turn the workpiece coordinate system da about X,)
(then db about Y, then dc about Z, and put its origin at dx dy dz:)
(work = d + R p. G54 is X10 Y20 Z-100; #5041.. read the workpiece)
(coordinates, #5021.. the machine's.)
(No. 00: dx 1. Set 1: dx 5 dy -2 dc 90: d = 6 -2 0, R turns X to Y:)
(  X10 Y0 Z5 -> 0 10 5 -> work X6 Y8 Z5, machine X16 Y28 Z-95.)
(Set 2: da 90 dc 90: X10 Y20 Z5 -> about X: 10 -5 20 -> about Z: 5 10 20)
(  -> + d = 1 0 0: work X6 Y10 Z20. G54.4 P0 cancels: X0 Y0 Z0 is work 0.)
G21 G90 G17 G94 F500.
G10 L2 P1 X10. Y20. Z-100.
G54 G0 X0 Y0 Z0
#26000 = 1.
#26010 = 5.
#26011 = -2.
#26015 = 90.
#26023 = 90.
#26025 = 90.
N1 G54.4 P1
N2 G1 X10. Y0 Z5.
#101 = #5041
#102 = #5042
#103 = #5043
#104 = #5021
#105 = #5022
#106 = #5023
N3 G54.4 P2
N4 G1 X10. Y20. Z5.
#111 = #5041
#112 = #5042
#113 = #5043
N5 G54.4 P0
N6 G1 X0 Y0 Z0
#121 = #5041
#122 = #5042
#123 = #5043
#124 = #26011
M30
%
