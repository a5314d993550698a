%
O9852 (SKIPNC PROBING LIBRARY - BROKEN TOOL CHECK ON A CONTACT TOOL SETTER)
(G65 P9852 T.. H..: the tool in the spindle, over the tool setter of)
(O9853 [#560, #561, #562, #563], goes down once, at #552, to H short of)
(the tip T's geometry + wear expects. No touch by there: 3093 BROKEN TOOL;)
(a touch more than H before the expected tip: 3088 OUT OF TOLERANCE [a)
(tool longer than set]. No offset changes. The tool returns as in O9853.)
(Results: #137 the length, #142 it less the expected.)
(Written for skipnc from the call interface only: docs/probing-cycles.md.)
#30=#4001
#31=#4003
#32=#4111
IF[[#20EQ#0]OR[#20LE0]OR[#11EQ#0]]THEN#3000=91(FORMAT ERROR)
IF[[#20NE[ROUND[#20]]]OR[#11LT0]]THEN#3000=91(FORMAT ERROR)
IF[[#560EQ#0]OR[#561EQ#0]OR[#562EQ#0]]THEN#3000=96(TOOL SETTER NOT CALIBRATED)
#175=1. (mm per program unit: 25.4 after G20)
IF[#4006EQ20]THEN#175=25.4
#12=#563
IF[#12EQ#0]THEN#12=5./#175
#13=#552
IF[#13EQ#0]THEN#13=1000./#175
#5=#[11000+#20]+#[10000+#20] (the expected length)
G49 (positions below are the gauge line's)
#6=#560+#5+#12
#7=#5023
IF[#7LT#6]THEN#7=#6
G90 G53 G0 Z#7
G53 X#561 Y#562
G53 Z#6
#8=#5023-#5043 (machine less work, Z)
#9=#560+#5-#11-#8 (H short of the expected tip, work)
G90 G31 Z#9 F#13
IF[ABS[#5063-#5083-#9]LT0.001]THEN#3000=93(BROKEN TOOL)
#137=#5063-#5083+#8-#560
#142=#137-#5
G53 G0 Z#7
IF[#142GT#11]THEN#3000=88(OUT OF TOLERANCE)
IF[#32EQ0]GOTO30
G43 H#32
N30 G#30 G#31
M99
%
