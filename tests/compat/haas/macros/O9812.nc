%
O9812 (WEB OR POCKET - OWN MACRO FOR THE COMPATIBILITY PROGRAMS)
(In the style of the call G65 P9812 X.. or Y.. [Z..] Q.. R.. S.. that)
(posts write; our own text. X or Y: the nominal width along that axis,)
(the probe starting over [web] or in [pocket] its nominal centre; Z: a)
(web, touched at that work Z from outside; without Z a pocket, touched)
(from inside at the present Z. Q overtravel, default 5; R clearance,)
(default 5; S the work offset to correct. Results: #135 or #136 the)
(centre, #138 the width, #140 or #141 the centre's error, #143 the)
(width's error.)
IF [#17 NE #0] GOTO 1
#17 = 5.
N1 IF [#18 NE #0] GOTO 2
#18 = 5.
N2 #30 = 1
#31 = #24
IF [#24 NE #0] GOTO 3
#30 = 2
#31 = #25
IF [#25 EQ #0] GOTO 98
N3 #32 = #[5040 + #30]
#33 = 1
IF [#26 EQ #0] GOTO 4
#33 = -1
N4 G65 P9819 A#30 B#33 C#32 D#31 Z#26 Q#17 R#18
#21 = [#148 + #149] / 2
IF [#30 EQ 2] GOTO 5
G0 X#21
GOTO 6
N5 G0 Y#21
N6 #[134 + #30] = #21
#138 = #148 - #149
#[139 + #30] = #21 - #32
#143 = #138 - #31
IF [#19 EQ #0] GOTO 9
IF [#19 LT 54] GOTO 7
#19 = #19 - 53
N7 #22 = 5200 + 20 * #19 + #30
#[#22] = #[#22] + #[139 + #30]
N9 M99
N98 #3000 = 93 (FORMAT ERROR - NO AXIS WORD)
M99
%
