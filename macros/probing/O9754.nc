%
O9754 (SKIPNC PROBING LIBRARY - CORNER RESULTS, INTERNAL)
(G65 P9754 X.. Y.. I.. J.. [A.. C..] [B..] [H..] [M..] [S..]: X Y the)
(corner found, I J its nominal, A C the angles of the faces across X and)
(across Y when measured: stores #135 #136 #139-#145, checks H on the)
(larger position error, M on the true position, B on the X face's angle)
(error [#148 = 4, alarm 3094], then corrects work offset S.)
#135=#24
#136=#25
#137=#0
#138=#0
#139=#1 (the X face's angle, nominal 90)
#140=#24-#4
#141=#25-#5
#142=#3 (the Y face's angle, nominal 0)
#143=#3 (its error)
#144=#0
IF[#1NE#0]THEN#144=#1-90. (the X face's angle error)
#8=ABS[#140]
IF[ABS[#141]GT#8]THEN#8=ABS[#141]
#145=2*SQRT[#140*#140+#141*#141]
#146=#0
G65 P9753 H#11 M#13 E#8
IF[[#2EQ#0]OR[#144EQ#0]]GOTO10
IF[ABS[#144]LE#2]GOTO10
#148=4
G65 P9758
#3000=94(ANGLE OUT OF TOL)
N10IF[#19EQ#0]GOTO90
G65 P9751 S#19 X#140 Y#141
N90M99
%
