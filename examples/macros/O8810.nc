%
O8810 (PROTECTED POSITIONING MOVE)
(G65 P8810 X.. Y.. Z.. F..  X Y Z: end point, work coordinates, any of them;)
(F: feed, mm/min, 3000 when omitted. The move is a skip move: if the probe)
(touches on the way, the program stops with alarm 3091 PATH OBSTRUCTED.)
#4=#5001 (end point of the previous block: the start)
#5=#5002
#6=#5003
IF[#24NE#0]THEN#4=#24
IF[#25NE#0]THEN#5=#25
IF[#26NE#0]THEN#6=#26
IF[#9EQ#0]THEN#9=3000.
G90 G31 X#4 Y#5 Z#6 F#9
IF[ABS[#5061-#4]GT0.001]GOTO91
IF[ABS[#5062-#5]GT0.001]GOTO91
IF[ABS[#5063-#5083-#6]GT0.001]GOTO91(#5063 has the length offset in it)
M99
N91#3000=91(PATH OBSTRUCTED)
%
