%
O9816 (SKIPNC PROBING LIBRARY - OUTER CORNER)
(G65 P9816 X.. Y.. [I.. J..] [Q..] [S..] [H..] [M..] [B..]: the probe)
(stands outside the)
(corner, off it in X and in Y, at the height of the touches; X and Y are)
(the nominal positions of its two faces, work coordinates. The face across)
(X is touched along X as far past the corner in Y as the probe starts off)
(it, the face across Y likewise; the probe returns to the start between)
(them and at the end. I J: a second touch on each face, J further along)
(the face across X from the corner, I along the face across Y. Q, S, H,)
(M, B and the results as in O9815.)
(Written for skipnc from the call interface only: docs/probing-cycles.md.)
#30=#4001
#31=#4003
IF[#550EQ#0]THEN#3000=95(PROBE STYLUS NOT CALIBRATED)
IF[[#24EQ#0]OR[#25EQ#0]]THEN#3000=91(FORMAT ERROR)
IF[[#24EQ#5001]OR[#25EQ#5002]]THEN#3000=91(FORMAT ERROR)
IF[[#4EQ#0]XOR[#5EQ#0]]THEN#3000=91(FORMAT ERROR)
#175=1. (mm per program unit: 25.4 after G20)
IF[#4006EQ20]THEN#175=25.4
IF[#17EQ#0]THEN#17=10./#175
#14=#5001
#15=#5002
#10=1
IF[#24LT#14]THEN#10=-1
#12=1
IF[#25LT#15]THEN#12=-1
G65 P9810 Y[2*#25-#15]
G65 P9750 X[#24+#10*[#17-#550]]
#27=#176+#10*#550
#150=#176
#151=#177
G65 P9810 X#14
IF[#4EQ#0]GOTO10
G65 P9810 Y[2*#25-#15+#12*ABS[#5]] (the second touch, further from the corner)
G65 P9750 X[#24+#10*[#17-#550]]
#152=#176
#153=#177
G65 P9810 X#14
N10G65 P9810 Y#15
G65 P9810 X[2*#24-#14]
G65 P9750 Y[#25+#12*[#17-#550]]
#28=#177+#12*#550
#154=#176
#155=#177
G65 P9810 Y#15
IF[#4EQ#0]GOTO20
G65 P9810 X[2*#24-#14+#10*ABS[#4]]
G65 P9750 Y[#25+#12*[#17-#550]]
#156=#176
#157=#177
G65 P9810 Y#15
N20G65 P9810 X#14
IF[#4EQ#0]GOTO30
G65 P9759 I#10 J#12
#27=#158
#28=#159
#32=#160
#33=#161
N30G65 P9754 X#27 Y#28 I#24 J#25 A#32 C#33 B#2 H#11 M#13 S#19
G65 P9757 W#23 X1. Y1.
G#30 G#31
M99
%
