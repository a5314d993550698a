%
O9759 (SKIPNC PROBING LIBRARY - CORNER FROM TWO LINES, INTERNAL)
(G65 P9759 I.. J..: #150 #151 and #152 #153 are two ball centres on the)
(face across X, touched along X in the direction I [1 or -1], #154 #155)
(and #156 #157 two on the face across Y, touched along Y in the)
(direction J. Each face is the line through its ball centres moved by)
(the ball's radius #550 along its normal, into the material; the corner)
(is where the two faces meet. Results: #158 #159 the corner, #160 the)
(face across X's angle from +X, 0 to 180, #161 the face across Y's,)
(-90 to 90. Written for skipnc: docs/probing-cycles.md.)
#1=#152-#150 (the X face's direction)
#2=#153-#151
#3=SQRT[#1*#1+#2*#2]
#7=#156-#154 (the Y face's direction)
#8=#157-#155
#6=SQRT[#7*#7+#8*#8]
IF[[#3LT0.000001]OR[#6LT0.000001]]THEN#3000=91(FORMAT ERROR)
#1=#1/#3
#2=#2/#3
#7=#7/#6
#8=#8/#6
#9=#2 (the X face's normal, toward the material: along I)
#10=-#1
IF[#9*#4LT0]THEN#10=#1
IF[#9*#4LT0]THEN#9=-#2
#11=#8 (the Y face's normal, along J)
#12=-#7
IF[#12*#5LT0]THEN#11=-#8
IF[#12*#5LT0]THEN#12=#7
#13=#150+#550*#9 (a point of each face)
#14=#151+#550*#10
#15=#154+#550*#11
#16=#155+#550*#12
#17=#1*#8-#2*#7
IF[ABS[#17]LT0.000001]THEN#3000=91(FORMAT ERROR)
#18=[[#15-#13]*#8-[#16-#14]*#7]/#17
#158=#13+#18*#1
#159=#14+#18*#2
#160=ATAN[#2]/[#1]
IF[#160GT180.]THEN#160=#160-180.
#161=ATAN[#8]/[#7]
IF[#161GT270.]THEN#161=#161-360.
IF[#161GT90.]THEN#161=#161-180.
M99
%
