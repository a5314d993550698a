%
O9756 (SKIPNC PROBING LIBRARY - TOOL OFFSET FEEDBACK, INTERNAL)
(G65 P9756 T.. E.. K.. [V..] [F..]: adds -F x E to the wear of tool offset)
(T, the length wear when K = 1, G10 L11, the radius wear when K = 2,)
(G10 L13, unless E is within the dead band V. F: the fraction fed back,)
(default 1. E: the error in the tool's terms: for a length, how much too)
(high the face was cut; for a radius, how much material was left on one)
(side. Keeps G90/G91 as it found it.)
IF[[#20LE0]OR[#20NE[ROUND[#20]]]]THEN#3000=91(FORMAT ERROR)
IF[#9EQ#0]THEN#9=1.
IF[[#22NE#0]AND[ABS[#8]LE#22]]GOTO90
#10=#4003
#11=10+2*#6-1 (L11 or L13)
G91 G10 L#11 P#20 R[-#9*#8]
G#10
N90M99
%
