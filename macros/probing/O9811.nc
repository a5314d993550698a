%
O9811 (SKIPNC PROBING LIBRARY - SINGLE SURFACE X, Y OR Z)
(G65 P9811 X.. or Y.. or Z.. [Q..] [S..] [H..] [M..]: the probe stands)
(in front of the surface; X, Y or Z is the surface's nominal position,)
(work coordinates. Touches it along that axis, returns to the start.)
(Q: overtravel past the nominal surface, default 10. S: work offset to)
(correct by the error, see O9751. H: tolerance of the surface position,)
(alarm 3088 OUT OF TOLERANCE; M: position tolerance, alarm 3089 OUT OF)
(POSITION; both checked before the offset is changed. T: a tool offset)
(whose wear takes the error, see O9756: Z the length, X Y the radius;)
(V its dead band, F the fraction fed back.)
(Results: #135 #136 or #137 the surface, #140 #141 or #142 its error,)
(#145 2 x the error's size, #146 metal condition, #147 the axis 1 2 3,)
(#148 0 or 1 size 2 position out of tolerance, #149 0.)
(Written for skipnc from the call interface only: docs/probing-cycles.md.)
#30=#4001
#31=#4003
#10=0 (the axis)
#12=0 (how many of X Y Z)
IF[#24NE#0]THEN#10=1
IF[#24NE#0]THEN#12=#12+1
IF[#25NE#0]THEN#10=2
IF[#25NE#0]THEN#12=#12+1
IF[#26NE#0]THEN#10=3
IF[#26NE#0]THEN#12=#12+1
IF[#12NE1]THEN#3000=91(FORMAT ERROR)
IF[[#550EQ#0]AND[#10LT3]]THEN#3000=95(PROBE STYLUS NOT CALIBRATED)
#175=1. (mm per program unit: 25.4 after G20)
IF[#4006EQ20]THEN#175=25.4
IF[#17EQ#0]THEN#17=10./#175
#14=#[23+#10] (nominal)
#15=#[5000+#10] (start)
#16=1 (direction of the touch)
IF[#14LT#15]THEN#16=-1
IF[#14EQ#15]THEN#3000=91(FORMAT ERROR)
#27=#550 (ball radius: the centre touches r before the surface in X, Y)
IF[#10EQ3]THEN#27=0 (the length offset reaches the ball's lowest point)
#28=#5001
#29=#5002
#32=#5003
IF[#10LT3]THEN#[27+#10]=#14+#16*[#17-#27]
IF[#10EQ3]THEN#32=#14+#16*#17
G65 P9750 X#28 Y#29 Z#32
#33=#[175+#10]+#16*#27 (the surface)
#28=#5001
#29=#5002
#32=#5003
IF[#10LT3]THEN#[27+#10]=#15
IF[#10EQ3]THEN#32=#15
G65 P9810 X#28 Y#29 Z#32
#135=#0
#136=#0
#137=#0
#140=#0
#141=#0
#142=#0
#[134+#10]=#33
#[139+#10]=#33-#14
#145=2*ABS[#33-#14]
#146=-#16*[#33-#14]
#147=#10
#148=0
#149=0
G65 P9757 W#23 K#10
IF[[#11NE#0]AND[ABS[#33-#14]GT#11]]THEN#148=1
IF[[#13NE#0]AND[ABS[#33-#14]GT#13]]THEN#148=#148+2
G65 P9758
IF[[#148EQ1]OR[#148EQ3]]THEN#3000=88(OUT OF TOLERANCE)
IF[#148EQ2]THEN#3000=89(OUT OF POSITION)
IF[#19EQ#0]GOTO90
#28=#0
#29=#0
#32=#0
IF[#10LT3]THEN#[27+#10]=#33-#14
IF[#10EQ3]THEN#32=#33-#14
G65 P9751 S#19 X#28 Y#29 Z#32
N90G#30 G#31
IF[#20EQ#0]GOTO95
#12=2 (the radius wear, by the material left)
#16=#146
IF[#10EQ3]THEN#12=1
IF[#10EQ3]THEN#16=#142 (the length wear, by how high the face is)
G65 P9756 T#20 E#16 K#12 V#22 F#9
N95M99
%
