%
O9814 (SKIPNC PROBING LIBRARY - BORE OR BOSS)
(G65 P9814 D.. [Z..] [R..] [Q..] [S..] [H..] [M..]: the probe stands at)
(the feature's nominal centre; D is its nominal diameter. Without Z: a)
(bore, touched from inside at this height. With Z and R >= 0: a boss,)
(touched from outside at Z, R the clearance outside the wall, default 5.)
(With Z and R < 0: a bore with an island, touched from inside at Z.)
(Q: overtravel, default 10. Touches X+ X- at the start, Y+ Y- at the X)
(centre, X+ X- again at the Y centre, and returns to the start. S, H, M,)
(T V F as in O9812, on the diameter and the true position.)
(Results: #135 #136 the centre, #138 the diameter: the mean of the last)
(two passes, #140 #141 the centre's error, #143 the diameter's error,)
(#145 true position error, #146 metal condition, #148, #149 0.)
(Written for skipnc from the call interface only: docs/probing-cycles.md.)
#30=#4001
#31=#4003
IF[#550EQ#0]THEN#3000=95(PROBE STYLUS NOT CALIBRATED)
IF[#7EQ#0]THEN#3000=91(FORMAT ERROR)
#175=1. (mm per program unit: 25.4 after G20)
IF[#4006EQ20]THEN#175=25.4
IF[#17EQ#0]THEN#17=10./#175
#14=#5001 (the nominal centre: the start)
#15=#5002
G65 P9752 A1 D#7 Z#26 R#18 Q#17
#16=#173
G65 P9810 X#16
G65 P9752 A2 D#7 Z#26 R#18 Q#17
#27=#173
#28=#174
G65 P9810 Y#27
G65 P9752 A1 D#7 Z#26 R#18 Q#17
#16=#173
G65 P9810 X#14 Y#15
#135=#16
#136=#27
#137=#0
#138=[#28+#174]/2
#140=#16-#14
#141=#27-#15
#142=#0
#143=#138-#7
#145=2*SQRT[#140*#140+#141*#141]
#146=#143 (from outside: a boss larger than nominal is more metal)
IF[[#26EQ#0]OR[#18LT0]]THEN#146=-#143
G65 P9757 W#23 D1. X1. Y1.
G65 P9753 H#11 M#13
IF[#19EQ#0]GOTO90
G65 P9751 S#19 X#140 Y#141
N90G#30 G#31
IF[#20EQ#0]GOTO95
G65 P9756 T#20 E[#146/2] K2. V#22 F#9 (radius wear: half the size's metal)
N95M99
%
