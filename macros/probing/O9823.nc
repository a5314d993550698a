%
O9823 (SKIPNC PROBING LIBRARY - BORE OR BOSS FROM THREE POINTS)
(G65 P9823 A.. B.. C.. D.. [Z..] [R..] [Q..] [S..] [H..] [M..]: the)
(probe stands at the nominal centre of a bore or boss, or of a part of)
(one, D across; A B C are the angles of the three touches, degrees from)
(+X. Z and R as in O9814: without Z a bore at this height, Z and R >= 0)
(a boss from outside, Z and R < 0 a bore with an island. The circle)
(through the three ball centres gives the centre and the diameter. Q, S,)
(H, M, T, V, F and the results as in O9814. Returns to the start.)
(Written for skipnc from the call interface only: docs/probing-cycles.md.)
#4=#4001 (modes to restore: I J K are not arguments here)
#5=#4003
IF[#550EQ#0]THEN#3000=95(PROBE STYLUS NOT CALIBRATED)
IF[[#1EQ#0]OR[#2EQ#0]OR[#3EQ#0]OR[#7EQ#0]]THEN#3000=91(FORMAT ERROR)
#175=1. (mm per program unit: 25.4 after G20)
IF[#4006EQ20]THEN#175=25.4
IF[#17EQ#0]THEN#17=10./#175
#14=#5001 (the nominal centre: the start)
#15=#5002
#10=1
WHILE[#10LE3]DO1
G65 P9755 A#[#10] D#7 Q#17 Z#26 R#18
#[25+2*#10]=#176-#14 (#27 #29 #31: X of each ball centre, from the start)
#[26+2*#10]=#177-#15 (#28 #30 #32: its Y)
#10=#10+1
END1
(the circle through the three points)
#33=2*[#27*[#30-#32]+#29*[#32-#28]+#31*[#28-#30]]
IF[ABS[#33]LT[0.000001]]THEN#3000=91(FORMAT ERROR)
#10=#27*#27+#28*#28
#12=#29*#29+#30*#30
#16=#31*#31+#32*#32
#140=[#10*[#30-#32]+#12*[#32-#28]+#16*[#28-#30]]/#33
#141=[#10*[#31-#29]+#12*[#27-#31]+#16*[#29-#27]]/#33
#10=SQRT[[#27-#140]*[#27-#140]+[#28-#141]*[#28-#141]] (the ball centres' radius)
#135=#14+#140
#136=#15+#141
#137=#0
#138=2*[#10+#550]
#146=-1 (from inside: a bore larger than nominal is less metal)
IF[[#26NE#0]AND[#18GE0]]THEN#138=2*[#10-#550]
IF[[#26NE#0]AND[#18GE0]]THEN#146=1
#142=#0
#143=#138-#7
#146=#146*#143
#145=2*SQRT[#140*#140+#141*#141]
G65 P9757 W#23 D1. X1. Y1.
G65 P9753 H#11 M#13
IF[#19EQ#0]GOTO90
G65 P9751 S#19 X#140 Y#141
N90G#4 G#5
IF[#20EQ#0]GOTO95
G65 P9756 T#20 E[#146/2] K2. V#22 F#9 (radius wear: half the size's metal)
N95M99
%
