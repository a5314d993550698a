%
O9810 (SKIPNC PROBING LIBRARY - PROTECTED POSITIONING)
(G65 P9810 X.. Y.. Z.. F..: a move to X Y Z, work coordinates, any of them,)
(as a skip move: if the probe touches on the way the axes stop and the)
(program stops with alarm 3086 PATH OBSTRUCTED. F: feed, kept in #551 for)
(the next call without F; 3000 mm/min, 118.11 in/min, before the first.)
(Written for skipnc from the call interface only: docs/probing-cycles.md.)
#30=#4001
#31=#4003
IF[#9NE#0]THEN#551=#9
#9=#551
#175=1. (mm per program unit: 25.4 after G20)
IF[#4006EQ20]THEN#175=25.4
IF[#9EQ#0]THEN#9=3000./#175
#1=#5001
#2=#5002
#3=#5003
IF[#24NE#0]THEN#1=#24
IF[#25NE#0]THEN#2=#25
IF[#26NE#0]THEN#3=#26
G90 G31 X#1 Y#2 Z#3 F#9
IF[[ABS[#5061-#1]GT[0.001]]OR[ABS[#5062-#2]GT[0.001]]OR[ABS[#5063-#5083-#3]GT[0.001]]]GOTO86
G#30 G#31
M99
N86#3000=86(PATH OBSTRUCTED)
%
