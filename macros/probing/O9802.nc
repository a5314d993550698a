%
O9802 (SKIPNC PROBING LIBRARY - BALL RADIUS ON A RING GAUGE)
(G65 P9802 D.. [Q..]: the probe stands near the centre of a ring gauge)
(whose diameter D is known, at the height to measure it. Touches it X+)
(X-, then Y+ Y- at the X centre found, then X+ X- again at the Y centre)
(found, as O9814, and sets the stylus ball's effective radius #550 so)
(that the ring reads D: half of D less the mean of the last two passes')
(spans between the ball's centres. Returns to the start. Q: overtravel,)
(default 10 mm.)
(Results: #550 and #138 = 2 x #550, the effective diameter; #135 #136)
(the ring's centre.)
(Written for skipnc in the manner of a ring-gauge calibration cycle; see)
(docs/probing-cycles.md.)
#30=#4001
#31=#4003
IF[#7EQ#0]THEN#3000=91(FORMAT ERROR)
#175=1. (mm per program unit: 25.4 after G20)
IF[#4006EQ20]THEN#175=25.4
IF[#17EQ#0]THEN#17=10./#175
#14=#5001
#15=#5002
#550=0 (the spans between the ball's centres: O9752 adds 2 x #550)
G65 P9752 A1 D#7 Q#17
#16=#173
G65 P9810 X#16
G65 P9752 A2 D#7 Q#17
#27=#173
#28=#174
G65 P9810 Y#27
G65 P9752 A1 D#7 Q#17
#16=#173
G65 P9810 X#14 Y#15
#550=[#7-[#28+#174]/2]/2
#135=#16
#136=#27
#138=2*#550
G#30 G#31
M99
%
