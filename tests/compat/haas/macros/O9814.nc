%
O9814 (BORE OR BOSS - OWN MACRO FOR THE COMPATIBILITY PROGRAMS)
(In the style of the call G65 P9814 D.. [Z..] Q.. R.. S.. that posts)
(write; our own text. D: the nominal diameter, the probe starting over)
([boss] or in [bore] its nominal centre; Z: a boss, touched at that work)
(Z from outside; without Z a bore, touched from inside at the present Z.)
(X first, then Y through the X centre found. Results: #135 #136 the)
(centre, #138 the diameter [the Y span, through the centre], #140 #141)
(the centre's error, #143 the diameter's error; S the work offset to)
(correct [X and Y].)
IF [#7 EQ #0] GOTO 98
IF [#17 NE #0] GOTO 1
#17 = 5.
N1 IF [#18 NE #0] GOTO 2
#18 = 5.
N2 #30 = #5041
#31 = #5042
#33 = 1
IF [#26 EQ #0] GOTO 3
#33 = -1
N3 G65 P9819 A1. B#33 C#30 D#7 Z#26 Q#17 R#18
#22 = [#148 + #149] / 2
G0 X#22
G65 P9819 A2. B#33 C#31 D#7 Z#26 Q#17 R#18
#23 = [#148 + #149] / 2
G0 Y#23
#135 = #22
#136 = #23
#138 = #148 - #149
#140 = #22 - #30
#141 = #23 - #31
#143 = #138 - #7
IF [#19 EQ #0] GOTO 9
IF [#19 LT 54] GOTO 4
#19 = #19 - 53
N4 #21 = 5200 + 20 * #19
#[#21 + 1] = #[#21 + 1] + #140
#[#21 + 2] = #[#21 + 2] + #141
N9 M99
N98 #3000 = 93 (FORMAT ERROR - NO DIAMETER D)
M99
%
