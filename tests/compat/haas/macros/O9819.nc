%
O9819 (TWO TOUCHES ACROSS A FEATURE - OWN ROUTINE SHARED BY O9812, O9814)
(A: the axis, 1 X or 2 Y; B: 1 from inside outward [bore, pocket] or -1)
(from outside inward [boss, web]; C: the nominal centre on that axis; D:)
(the nominal width; Z: the work Z of the touches of a boss or web [the)
(probe goes out by R, down to Z, touches inward, comes back up]; Q:)
(overtravel past each nominal edge; R: radial clearance. One touch at)
(F300 a side, the + side first. Results: #148 the + edge, #149 the - edge.)
#32 = #5043 - #5083
#27 = 1
N1 #28 = #3 + #27 * [#7 / 2]
IF [#2 GT 0] GOTO 10
#29 = #28 + #27 * #18
IF [#1 EQ 2] GOTO 2
G0 X#29
GOTO 3
N2 G0 Y#29
N3 G0 Z#26
#30 = #28 - #27 * #17
GOTO 11
N10 #30 = #28 + #27 * #17
N11 IF [#1 EQ 2] GOTO 12
G31 X#30 F300.
#31 = #5061
GOTO 13
N12 G31 Y#30 F300.
#31 = #5062
N13 IF [ABS[#31 - #30] LT 0.0005] GOTO 97
#33 = #31 + #27 * #2 * #556
IF [#27 LT 0] GOTO 20
#148 = #33
GOTO 21
N20 #149 = #33
N21 IF [#2 GT 0] GOTO 30
IF [#1 EQ 2] GOTO 22
G0 X#29
GOTO 23
N22 G0 Y#29
N23 G0 Z#32
GOTO 31
N30 IF [#1 EQ 2] GOTO 32
G0 X#3
GOTO 31
N32 G0 Y#3
N31 IF [#27 LT 0] GOTO 40
#27 = -1
GOTO 1
N40 M99
N97 #3000 = 92 (PROBE OPEN - NO SURFACE FOUND)
M99
%
