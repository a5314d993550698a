%
O9843 (SKIPNC PROBING LIBRARY - ANGLE OF A SURFACE, X OR Y)
(G65 P9843 X.. or Y.. D.. [A..] [Q..] [B..]: the probe stands in front of)
(a surface; X or Y is its nominal position, work coordinates. Touches it)
(along that axis here, returns, moves D along the surface, along Y for an)
(X surface, along X for a Y surface, touches it again and returns to the)
(start. A: the surface's nominal angle from +X, counter-clockwise, default)
(90 for X, 0 for Y. Q: overtravel, default 10. B: tolerance on the)
(angle's error, alarm 3094 ANGLE OUT OF TOL.)
(Results: #135 or #136 the surface at the first touch, #140 or #141 its)
(error, #139 the angle of the surface, from +X, within 180 of A, #144 its)
(error, #148 0 or 4 out of B, #149 0.)
(Written for skipnc from the call interface only: docs/probing-cycles.md.)
#30=#4001
#31=#4003
IF[#550EQ#0]THEN#3000=95(PROBE STYLUS NOT CALIBRATED)
IF[[#24NE#0]XOR[#25EQ#0]]THEN#3000=91(FORMAT ERROR)
IF[[#7EQ#0]OR[#7EQ0]]THEN#3000=91(FORMAT ERROR)
#10=1 (the axis touched)
IF[#25NE#0]THEN#10=2
#12=3-#10 (the axis along the surface)
IF[[#1EQ#0]AND[#10EQ1]]THEN#1=90.
IF[[#1EQ#0]AND[#10EQ2]]THEN#1=0
#175=1. (mm per program unit: 25.4 after G20)
IF[#4006EQ20]THEN#175=25.4
IF[#17EQ#0]THEN#17=10./#175
#14=#[23+#10] (nominal)
#15=#5001
#16=#5002
IF[#14EQ#[14+#10]]THEN#3000=91(FORMAT ERROR)
#27=1 (direction of the touches)
IF[#14LT#[14+#10]]THEN#27=-1
#28=#15
#29=#16
#[27+#10]=#14+#27*[#17-#550]
G65 P9750 X#28 Y#29
#32=#[175+#10]+#27*#550 (the first touch's surface)
G65 P9810 X#15 Y#16
#28=#15
#29=#16
#[27+#12]=#[27+#12]+#7
G65 P9810 X#28 Y#29
#[27+#10]=#14+#27*[#17-#550]
G65 P9750 X#28 Y#29
#33=#[175+#10]+#27*#550 (the second touch's surface)
#[27+#10]=#[14+#10]
G65 P9810 X#28 Y#29
G65 P9810 X#15 Y#16
#28=#33-#32 (the line from the first to the second: dx, dy)
#29=#7
IF[#10EQ2]THEN#29=#28
IF[#10EQ2]THEN#28=#7
IF[#7LT0]THEN#28=-#28
IF[#7LT0]THEN#29=-#29
#139=ATAN[#29]/[#28]
IF[[#139-#1]GT180.]THEN#139=#139-360.
IF[[#139-#1]LT-180.]THEN#139=#139+360.
#135=#0
#136=#0
#140=#0
#141=#0
#[134+#10]=#32
#[139+#10]=#32-#14
#144=#139-#1
#145=#0
#148=0
#149=0
G65 P9757 W#23 A1.
IF[[#2NE#0]AND[ABS[#144]GT#2]]THEN#148=4
G65 P9758
IF[#148EQ4]THEN#3000=94(ANGLE OUT OF TOL)
G#30 G#31
M99
%
