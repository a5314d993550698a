%
O9750 (SKIPNC PROBING LIBRARY - ONE MEASURED TOUCH, INTERNAL)
(G65 P9750 X.. Y.. Z..: from where the probe stands toward that point, work)
(coordinates of the programmed point: a fast touch at #552, a back-off of)
(#558 along the same line, a slow touch at #553 and the same back-off,)
(which releases the stylus. Axes left out stay.)
(Results: #176 #177 #178, the slow touch's X Y Z, work coordinates of the)
(programmed point: #5061, #5062 and #5063 less the length offset #5083.)
(No touch before the point: alarm 3087 PROBE FAIL. A touch where the move)
(starts, the stylus already deflected: alarm 3092 PROBE OPEN.)
(Written for skipnc; see docs/probing-cycles.md.)
#1=#5001
#2=#5002
#3=#5003
IF[#24EQ#0]THEN#24=#1
IF[#25EQ#0]THEN#25=#2
IF[#26EQ#0]THEN#26=#3
#4=#24-#1
#5=#25-#2
#6=#26-#3
#7=SQRT[#4*#4+#5*#5+#6*#6]
IF[#7LT0.001]THEN#3000=91(FORMAT ERROR)
#175=1. (mm per program unit: 25.4 after G20)
IF[#4006EQ20]THEN#175=25.4
#12=#552 (the fast feed)
#13=#553 (the slow feed)
#14=#558 (the back-off)
IF[#12EQ#0]THEN#12=1000./#175
IF[#13EQ#0]THEN#13=100./#175
IF[#14EQ#0]THEN#14=1./#175
#8=1
WHILE[#8LE2]DO1
#9=#12
IF[#8EQ2]THEN#9=#13
G90 G31 X#24 Y#25 Z#26 F#9
IF[[ABS[#5061-#24]LT[0.001]]AND[ABS[#5062-#25]LT[0.001]]AND[ABS[#5063-#5083-#26]LT[0.001]]]THEN#3000=87(PROBE FAIL)
#176=#5061
#177=#5062
#178=#5063-#5083
#10=[#176-#1]*#4+[#177-#2]*#5+[#178-#3]*#6
IF[#10LT[0.0001*#7]]THEN#3000=92(PROBE OPEN)
(back off along the line of the move, at most to where it started)
#11=#14
IF[#11GT[#10/#7]]THEN#11=#10/#7
#1=#176-#4/#7*#11
#2=#177-#5/#7*#11
#3=#178-#6/#7*#11
G90 G01 X#1 Y#2 Z#3 F#12
#8=#8+1
END1
M99
%
