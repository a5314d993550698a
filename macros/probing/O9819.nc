%
O9819 (SKIPNC PROBING LIBRARY - HOLES OR BOSSES ON A PITCH CIRCLE)
(G65 P9819 A.. B.. C.. D.. K.. or Z.. [R..] [Q..] [S..] [H..] [M..]: the)
(probe stands over the pitch circle's nominal centre, clear of the part.)
(B features, D across, on a circle C across, the first at A degrees from)
(+X, the others 360 / B apart counter-clockwise, B 2 to 10. With K:)
(holes, each measured as O9814 measures a bore at the height K; with Z:)
(bosses, each from outside at Z, R the clearance. Between features the)
(probe moves at the start's height. The pitch circle's centre is the mean of)
(the features' centres, its diameter twice their mean distance from it.)
(Results: #135 #136 the circle's centre, #138 the features' mean)
(diameter, #139 the first feature's angle, #140 #141 the centre's error,)
(#142 the pitch circle's error, #143 the features' size error, #144 the)
(angle's error, #145 true position error of the centre, #147 B. S: work)
(offset to correct by the centre's error; H on #143, M on #145.)
(Written for skipnc from the call interface only: docs/probing-cycles.md.)
#30=#4001
#31=#4003
IF[#550EQ#0]THEN#3000=95(PROBE STYLUS NOT CALIBRATED)
IF[[#1EQ#0]OR[#3EQ#0]OR[#7EQ#0]]THEN#3000=91(FORMAT ERROR)
IF[[#2LT2]OR[#2GT10]OR[#2NE[ROUND[#2]]]]THEN#3000=91(FORMAT ERROR)
IF[[#6NE#0]XOR[#26EQ#0]]THEN#3000=91(FORMAT ERROR)
#175=1. (mm per program unit: 25.4 after G20)
IF[#4006EQ20]THEN#175=25.4
IF[#17EQ#0]THEN#17=10./#175
#14=#5001 (the nominal centre: the start)
#15=#5002
#16=#5003
#27=0 (sums: X, Y of the centres, diameters)
#28=0
#29=0
#10=0
WHILE[#10LT#2]DO1
#12=#1+#10*360/#2
G65 P9810 X[#14+#3/2*COS[#12]] Y[#15+#3/2*SIN[#12]]
IF[#6NE#0]THEN#32=#6 (a hole: down to K, then a bore)
IF[#6NE#0]GOTO10
G65 P9814 D#7 Z#26 R#18 Q#17
GOTO20
N10G65 P9810 Z#32
G65 P9814 D#7 Q#17
G65 P9810 Z#16
N20#27=#27+#135
#28=#28+#136
#29=#29+#138
#[150+#10]=#135 (the centres, kept for the mean distance)
#[160+#10]=#136
#10=#10+1
END1
G65 P9810 X#14 Y#15
#135=#27/#2
#136=#28/#2
#138=#29/#2
#33=0
#10=0
WHILE[#10LT#2]DO1
#33=#33+SQRT[[#[150+#10]-#135]*[#[150+#10]-#135]+[#[160+#10]-#136]*[#[160+#10]-#136]]
#10=#10+1
END1
#139=ATAN[#160-#136]/[#150-#135]
IF[[#139-#1]GT180.]THEN#139=#139-360.
IF[[#139-#1]LT-180.]THEN#139=#139+360.
#137=#0
#140=#135-#14
#141=#136-#15
#142=2*#33/#2-#3
#143=#138-#7
#144=#139-#1
#145=2*SQRT[#140*#140+#141*#141]
#146=#0
#147=#2
G65 P9753 H#11 M#13
IF[#19EQ#0]GOTO90
G65 P9751 S#19 X#140 Y#141
N90G#30 G#31
M99
%
