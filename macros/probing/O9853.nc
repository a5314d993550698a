%
O9853 (SKIPNC PROBING LIBRARY - TOOL LENGTH ON A CONTACT TOOL SETTER)
(G65 P9853 T.. [B0] [H..] [Q..]: the tool in the spindle is measured on)
(the contact tool setter whose trigger height, machine Z of the tip, is)
(#560 and whose centre is machine X #561 Y #562. T: its length offset;)
(the expected length is T's geometry + wear. The tool goes up, over the)
(setter at #563 [default 5] above the expected tip, and is touched down)
(at most Q [default 10] past it. B: 0 or left out, length only. Without H)
(T's geometry is set to the length and its wear to 0; with H a check only:)
(a length off the expected by more than H stops with 3093 BROKEN TOOL and)
(no offset changes. The tool returns to the height it started at or the)
(approach height, the higher, over the setter; the H active before is)
(active again. Results: #137 the length, #142 it less the expected.)
(Written for skipnc from the call interface only: docs/probing-cycles.md.)
#30=#4001
#31=#4003
#32=#4111
IF[[#20EQ#0]OR[#20LE0]]THEN#3000=91(FORMAT ERROR)
IF[#20NE[ROUND[#20]]]THEN#3000=91(FORMAT ERROR)
IF[[#2NE#0]AND[#2NE0]]THEN#3000=91(FORMAT ERROR)
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
N20 IF[#32EQ0]GOTO30
G43 H#32
N30 G#30 G#31
M99
%
