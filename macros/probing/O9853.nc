%
O9853 (SKIPNC PROBING LIBRARY - TOOL LENGTH AND DIAMETER ON A CONTACT SETTER)
(G65 P9853 T.. [B..] [D..] [H..] [Q..]: the tool in the spindle is measured)
(on the contact tool setter whose trigger height, machine Z of the tip, is)
(#560 and whose centre is machine X #561 Y #562. T: its length offset;)
(the expected length is T's geometry + wear. B0 or left out: length. The)
(tool goes up, over the setter at #563 [default 5] above the expected tip,)
(and is touched down at most Q [default 10] past it. B1: diameter, B2:)
(length, then diameter. D: its diameter offset [default T]; the expected)
(radius is D's geometry + wear. The tool, its tip #567 [default 2] below)
(#560, is touched against the side of the setter's disc, effective radius)
(#566 [its radius less the pre-travel], from +X and from -X, each from)
(#563 out and at most Q past where the expected radius puts it. Without H)
(T's geometry is set to the length, D's to the radius, their wear to 0;)
(with H a check only: a length off the expected by more than H stops with)
(3093 BROKEN TOOL, a diameter off by more than H with 3088 OUT OF)
(TOLERANCE, and no offset changes. The tool returns to the height it)
(started at or the approach height, the higher, over the setter; the H)
(active before is active again. Results: #137 the length, #142 it less)
(the expected; #138 the diameter, #143 it less the expected, #135 the)
(touches' midpoint less #561.)
(Written for skipnc from the call interface only: docs/probing-cycles.md.)
#30=#4001
#31=#4003
#32=#4111
IF[[#20EQ#0]OR[#20LE0]]THEN#3000=91(FORMAT ERROR)
IF[#20NE[ROUND[#20]]]THEN#3000=91(FORMAT ERROR)
IF[#2EQ#0]THEN#2=0
IF[[#2NE0]AND[#2NE1]AND[#2NE2]]THEN#3000=91(FORMAT ERROR)
#27=#7 (the diameter offset)
IF[#27EQ#0]THEN#27=#20
IF[[#27LE0]OR[#27NE[ROUND[#27]]]]THEN#3000=91(FORMAT ERROR)
IF[[#2NE0]AND[#566EQ#0]]THEN#3000=96(TOOL SETTER NOT CALIBRATED)
IF[[#560EQ#0]OR[#561EQ#0]OR[#562EQ#0]]THEN#3000=96(TOOL SETTER NOT CALIBRATED)
#175=1. (mm per program unit: 25.4 after G20)
IF[#4006EQ20]THEN#175=25.4
IF[#17EQ#0]THEN#17=10./#175
#12=#563
IF[#12EQ#0]THEN#12=5./#175
#5=#[11000+#20]+#[10000+#20] (the expected length)
G49 (positions below are the gauge line's)
#6=#560+#5+#12 (the approach height, machine)
#7=#5023
IF[#7LT#6]THEN#7=#6
G90 G53 G0 Z#7
G53 X#561 Y#562
IF[#2EQ1]GOTO40
G53 Z#6
#8=#5023-#5043 (machine less work, Z)
G65 P9750 Z[#560+#5-#17-#8]
#137=#178+#8-#560
#142=#137-#5
G53 G0 Z#7
IF[#11EQ#0]GOTO10
IF[ABS[#142]GT#11]THEN#3000=93(BROKEN TOOL)
GOTO20
N10 G90 G10 L10 P#20 R#137
G10 L11 P#20 R0
N20 IF[#2EQ0]GOTO90
#5=#137 (the diameter is taken at the length just measured)
N40 #14=#566
#15=#567
IF[#15EQ#0]THEN#15=2./#175
#16=#[13000+#27]+#[12000+#27] (the expected radius)
#6=#560+#5+#12
IF[#7LT#6]THEN#7=#6
#8=#5021-#5041 (machine less work, X)
#10=1 (the side: +X, then -X)
WHILE[#10GE-1]DO1
G53 G0 Z#6
G53 X[#561+#10*[#16+#14+#12]] Y#562
G53 Z[#560+#5-#15]
G65 P9750 X[#561+#10*[#16+#14-#17]-#8]
#[28+[1-#10]/2]=#176+#8 (#28 from +X, #29 from -X)
#10=#10-2
END1
G53 G0 Z#7
G53 X#561
#138=#28-#29-2*#14
#143=#138-2*#16
#135=[#28+#29]/2-#561
IF[#11EQ#0]GOTO50
IF[ABS[#143]GT#11]THEN#3000=88(OUT OF TOLERANCE)
GOTO90
N50 G90 G10 L12 P#27 R[#138/2]
G10 L13 P#27 R0
N90 IF[#32EQ0]GOTO30
G43 H#32
N30 G#30 G#31
M99
%
