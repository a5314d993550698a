%
O9752 (SKIPNC PROBING LIBRARY - TWO OPPOSITE TOUCHES, INTERNAL)
(G65 P9752 A.. D.. Q.. [Z.. R..]: from the feature's nominal centre, where)
(the probe stands, touches both walls along axis A, 1 X or 2 Y, of a)
(feature D wide: without Z from inside at this height, a pocket or bore;)
(with Z and R >= 0 from outside at Z, a web or boss, R the clearance)
(outside the wall, default 5; with Z and R < 0 from inside at Z, an island)
(in the way at this height, R the clearance inside the wall. Q: overtravel)
(past the nominal wall. Returns to the start. Results: #173 the centre and)
(#174 the width on that axis, work coordinates.)
#2=#5001
#3=#5002
#4=#5003
#5=#550
#6=1 (1: touched from inside, 0: from outside)
IF[#26NE#0]THEN#6=0
IF[[#26NE#0]AND[#18LT0]]THEN#6=1
IF[[#26NE#0]AND[#18EQ#0]]THEN#18=5./#175
#8=#[1+#1] (the start on the axis)
#9=1 (the side: +1, then -1)
WHILE[#9GE-1]DO1
#10=#8+#9*[#7/2-#5+#17] (touch target from inside)
#11=#8+#9*[#7/2-#5+#18] (clearance point inside, R < 0)
IF[#6EQ1]GOTO10
#10=#8+#9*[#7/2+#5-#17] (touch target from outside)
#11=#8+#9*[#7/2+#5+#18] (clearance point outside)
N10#15=#2
#16=#3
#[14+#1]=#11
IF[#26EQ#0]GOTO20
G65 P9810 X#15 Y#16
G65 P9810 Z#26
N20#15=#2
#16=#3
#[14+#1]=#10
G65 P9750 X#15 Y#16
#12=#[175+#1]
IF[#9EQ1]THEN#13=#12
IF[#9EQ-1]THEN#14=#12
#15=#2
#16=#3
#[14+#1]=#11
IF[#26EQ#0]GOTO30
G65 P9810 X#15 Y#16
G65 P9810 Z#4
N30G65 P9810 X#2 Y#3
#9=#9-2
END1
#173=[#13+#14]/2
#174=#13-#14+2*#5
IF[#6EQ0]THEN#174=#13-#14-2*#5
M99
%
