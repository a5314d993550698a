%
O9754 (SKIPNC PROBING LIBRARY - CORNER RESULTS, INTERNAL)
(G65 P9754 X.. Y.. I.. J.. [H..] [M..] [S..]: X Y the corner found, I J)
(its nominal: stores #135 #136 #140 #141 #145, checks H on the larger)
(error and M on the true position, then corrects work offset S.)
#135=#24
#136=#25
#137=#0
#138=#0
#140=#24-#4
#141=#25-#5
#142=#0
#143=ABS[#140]
IF[ABS[#141]GT#143]THEN#143=ABS[#141]
#145=2*SQRT[#140*#140+#141*#141]
#146=#0
G65 P9753 H#11 M#13
#143=#0
IF[#19EQ#0]GOTO90
G65 P9751 S#19 X#140 Y#141
N90M99
%
