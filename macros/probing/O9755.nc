%
O9755 (SKIPNC PROBING LIBRARY - ONE TOUCH ALONG A RADIUS, INTERNAL)
(G65 P9755 A.. D.. Q.. [Z.. R..]: from the nominal centre of a circle D)
(across, where the probe stands, touches its wall at the angle A, degrees)
(from +X: without Z from inside at this height; with Z and R >= 0 from)
(outside at Z, R the clearance outside the wall, default 5; with Z and)
(R < 0 from inside at Z, R the clearance inside. Returns to the start.)
(Results: #176 #177, the ball's centre at the touch, work coordinates.)
#2=#5001
#3=#5002
#4=#5003
#5=COS[#1]
#6=SIN[#1]
#8=#7/2-#550+#17 (from the centre to the touch's end, inside)
#9=#7/2-#550+#18 (to the clearance point inside, R < 0)
IF[#26EQ#0]GOTO10
IF[#18EQ#0]THEN#18=5./#175
IF[#18LT0]GOTO10
#8=#7/2+#550-#17 (outside)
#9=#7/2+#550+#18
N10IF[#26EQ#0]GOTO20
G65 P9810 X[#2+#9*#5] Y[#3+#9*#6]
G65 P9810 Z#26
N20G65 P9750 X[#2+#8*#5] Y[#3+#8*#6]
IF[#26EQ#0]GOTO30
G65 P9810 X[#2+#9*#5] Y[#3+#9*#6]
G65 P9810 Z#4
N30G65 P9810 X#2 Y#3
M99
%
