%
O9811 (SINGLE SURFACE - OWN MACRO FOR THE COMPATIBILITY PROGRAMS)
(In the style of the call G65 P9811 X.. or Y.. or Z.. Q.. S.. that posts)
(write; our own text. X, Y or Z: the surface's nominal position, work)
(coordinates; Q: overtravel past it, default 5; S: the work offset to)
(correct, 1-6 or 54-59 = G54-G59. One touch at F300 from where the probe)
(is, then back there. #556: the ball's calibrated radius. Results: #135)
(#136 #137 the surface on X, Y or Z, #140 #141 #142 its error from the)
(nominal. No touch: alarm 92. No axis word: alarm 93.)
IF [#17 NE #0] GOTO 1
#17 = 5.
N1 #30 = 1
#31 = #24
IF [#24 NE #0] GOTO 2
#30 = 2
#31 = #25
IF [#25 NE #0] GOTO 2
#30 = 3
#31 = #26
IF [#26 EQ #0] GOTO 98
N2 #32 = #[5040 + #30]
IF [#30 NE 3] GOTO 3
#32 = #32 - #5083
N3 #33 = 1
IF [#31 GT #32] GOTO 4
#33 = -1
N4 #21 = #31 + #33 * #17
IF [#30 EQ 2] GOTO 12
IF [#30 EQ 3] GOTO 13
G31 X#21 F300.
GOTO 14
N12 G31 Y#21 F300.
GOTO 14
N13 G31 Z#21 F300.
N14 #22 = #[5060 + #30]
IF [#30 NE 3] GOTO 15
#22 = #22 - #5083
N15 IF [ABS[#22 - #21] LT 0.0005] GOTO 97
#23 = #22 + #33 * #556
#[134 + #30] = #23
#[139 + #30] = #23 - #31
IF [#30 EQ 2] GOTO 22
IF [#30 EQ 3] GOTO 23
G0 X#32
GOTO 24
N22 G0 Y#32
GOTO 24
N23 G0 Z#32
N24 IF [#19 EQ #0] GOTO 30
IF [#19 LT 54] GOTO 25
#19 = #19 - 53
N25 #27 = 5200 + 20 * #19 + #30
#[#27] = #[#27] + #[139 + #30]
N30 M99
N97 #3000 = 92 (PROBE OPEN - NO SURFACE FOUND)
N98 #3000 = 93 (FORMAT ERROR - NO AXIS WORD)
M99
%
