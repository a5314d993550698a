%
O9812 (SKIPNC PROBING LIBRARY - WEB OR POCKET)
(G65 P9812 X.. or Y.. [Z..] [R..] [Q..] [S..] [H..] [M..]: the probe)
(stands at the feature's nominal centre; X or Y is its nominal width.)
(Without Z: a pocket or slot, touched from inside at this height. With Z)
(and R >= 0: a web, touched from outside at Z, R the clearance outside)
(the wall, default 5. With Z and R < 0: a pocket with an island, touched)
(from inside at Z. Q: overtravel, default 10. Returns to the start.)
(S: work offset to correct by the centre's error, see O9751. H: size)
(tolerance, alarm 3088 OUT OF TOLERANCE; M: position tolerance on the)
(true position #145, alarm 3089 OUT OF POSITION; checked before S.)
(T V F: the radius wear of tool offset T takes half the width's metal)
(condition, see O9756.)
(Results: #135 or #136 the centre, #138 the width, #140 or #141 the)
(centre's error, #143 the width's error, #145 true position error, #146)
(metal condition, #147 the axis 1 2, #148 0 or 1 size 2 position, #149 0.)
(Written for skipnc from the call interface only: docs/probing-cycles.md.)
#30=#4001
#31=#4003
IF[#550EQ#0]THEN#3000=95(PROBE STYLUS NOT CALIBRATED)
IF[[#24NE#0]XOR[#25EQ#0]]THEN#3000=91(FORMAT ERROR)
#10=1
#12=#24
IF[#25NE#0]THEN#10=2
IF[#25NE#0]THEN#12=#25
#175=1. (mm per program unit: 25.4 after G20)
IF[#4006EQ20]THEN#175=25.4
IF[#17EQ#0]THEN#17=10./#175
#14=#[5000+#10] (the nominal centre: the start)
G65 P9752 A#10 D#12 Z#26 R#18 Q#17
#135=#0
#136=#0
#140=#0
#141=#0
#[134+#10]=#173
#138=#174
#[139+#10]=#173-#14
#143=#174-#12
#145=2*ABS[#173-#14]
#146=#143 (from outside: a web wider than nominal is more metal)
IF[[#26EQ#0]OR[#18LT0]]THEN#146=-#143
#147=#10
G65 P9757 W#23 D1. K#10
G65 P9753 H#11 M#13
IF[#19EQ#0]GOTO90
#15=#0
#16=#0
#[14+#10]=#173-#14
G65 P9751 S#19 X#15 Y#16
N90G#30 G#31
IF[#20EQ#0]GOTO95
G65 P9756 T#20 E[#146/2] K2. V#22 F#9 (radius wear: half the size's metal)
N95M99
%
