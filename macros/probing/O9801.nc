%
O9801 (SKIPNC PROBING LIBRARY - PROBE LENGTH ON A REFERENCE SURFACE)
(G65 P9801 Z.. [T..] [Q..]: the probe stands above a surface whose height)
(Z is known, work coordinates, under G43 with its length offset. Touches)
(it downward and corrects the length offset T, default the active H, so)
(that the lowest point of the ball reads Z: the length runs from the gauge)
(line to the ball's lowest point. Then G43 H again when T is the active H,)
(and back to the start. Q: overtravel below Z, default 10.)
(Results: #137 the height read before the correction, #142 the correction)
(added to the offset's geometry.)
(Written for skipnc from the call interface only: docs/probing-cycles.md.)
#30=#4001
#31=#4003
IF[#26EQ#0]THEN#3000=91(FORMAT ERROR)
IF[#20EQ#0]THEN#20=#4111
IF[[#20EQ#0]OR[#5083EQ0]]THEN#3000=91(FORMAT ERROR)
#175=1. (mm per program unit: 25.4 after G20)
IF[#4006EQ20]THEN#175=25.4
IF[#17EQ#0]THEN#17=10./#175
#10=#5003 (the start)
IF[#26GE#10]THEN#3000=91(FORMAT ERROR)
G65 P9750 Z[#26-#17]
#137=#178
#142=#178-#26
G91 G10 L10 P#20 R#142
G90
IF[#4111NE#20]GOTO10
G43 H#20
N10G65 P9810 Z#10
G#30 G#31
M99
%
