%
O9753 (SKIPNC PROBING LIBRARY - TOLERANCE CHECK, INTERNAL)
(G65 P9753 H.. M.. [E..]: #148 = 1 when the size error #143 [E when)
(given] is larger than H,)
(+ 2 when the true position error #145 is larger than M; then alarm 3088)
(OUT OF TOLERANCE, or 3089 OUT OF POSITION when only the position is.)
#148=0
#149=0
#33=#143
IF[#8NE#0]THEN#33=#8
IF[[#11NE#0]AND[ABS[#33]GT#11]]THEN#148=1
IF[[#13NE#0]AND[#145GT#13]]THEN#148=#148+2
G65 P9758
IF[[#148EQ1]OR[#148EQ3]]THEN#3000=88(OUT OF TOLERANCE)
IF[#148EQ2]THEN#3000=89(OUT OF POSITION)
M99
%
