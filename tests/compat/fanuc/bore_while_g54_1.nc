%
O1002 (BORE CENTRE INTO G54.1 P5)
( Compatibility: in the style of the Fanuc macro B bore-finding programs )
( of shop forums and of the public "dimple measurement" macros O23001/ )
( O23002 [one G91 G31 per direction, #5061/#5062 read, #3000 on a bad )
( argument], written as one WHILE loop over +X -X +Y -Y. )
( Constructs: G65 with D K F S arguments, WHILE [..] DO1 / END1, FIX and )
( arithmetic on the loop counter to pick the axis and sign, G31 X.. Y.. )
( with both words [one of them not moving], #5041/#5042 [current work )
( position], #[140 + n] arrays, IF [..] THEN, G10 L20 P5 [G54.1 P5], )
( #7081/#7082, G54.1 P5 selected afterwards, #3000 when the size is off. )
( Expected by hand [scene: bore centre X12.345 Y-6.789, radius 15; ball )
( radius 1; G54 = machine]: from X12 Y-7 the X touches are symmetric about )
( X12.345 whatever the Y [#140, #141 = 12.345 +- [SQRT[15^2 - 0.211^2] - 1] )
( = 26.343516, -1.653516]: the X centre is 12.345. From there the Y touches )
( are -6.789 + 14 = 7.211 and -6.789 - 14 = -20.789: Y centre -6.789, the )
( size 7.211 + 20.789 + 2 x 1 = 30.000 [#100]. G10 L20 P5 stores the centre )
( [G54 is zero]: #7081 = 12.345, #7082 = -6.789; G54.1 P5 X0 Y0 ends at )
( machine X12.345 Y-6.789. #101 = 5 [#4130, the P of G54.1]. )
G90 G17 G40 G49 G80 G21
G91 G28 Z0
G90 G54 G0 X12. Y-7.
G43 H20 Z-210.
G1 Z-240. F1000.
G65 P9110 D30. K5. F150. S5.
G54.1 P5 G0 X0 Y0
#101 = #4130
G0 Z100.
M30
O9110 (BORE: D SIZE, K OVERTRAVEL, F FEED, S G54.1 P NUMBER)
IF [#7 EQ #0] GOTO 91
IF [#19 EQ #0] GOTO 91
#30 = #5041
#31 = #5042
#29 = #7 / 2 + #6 (HOW FAR EACH TOUCH MAY GO)
#32 = 0
WHILE [#32 LT 4] DO1
#28 = FIX[#32 / 2] (0: X, 1: Y)
#33 = 1 - 2 * [#32 - 2 * #28] (+1, -1)
G90 G31 X[#30 + [1 - #28] * #33 * #29] Y[#31 + #28 * #33 * #29] F#9
#[140 + #32] = #[5061 + #28]
G0 X#30 Y#31
IF [#32 EQ 1] THEN #30 = [#140 + #141] / 2
G0 X#30
#32 = #32 + 1
END1
#31 = [#142 + #143] / 2
G0 Y#31
#100 = #142 - #143 + 2.0 (BALL DIAMETER 2)
IF [ABS[#100 - #7] GT 0.5] GOTO 92
G10 L20 P#19 X[#5221 + #30] Y[#5222 + #31]
M99
N91 #3000 = 91 (ARGUMENT MISSING)
N92 #3000 = 92 (BORE SIZE OUT OF TOLERANCE)
M99
%
