%
O1001 (Z SURFACE TOUCH, G54 Z SET BY G10 L2)
( Compatibility: in the style of the Fanuc custom macro B single-surface )
( macros of shop blogs and forums [cnc.wiki/en/g31-skip-function-and-probe-usage, )
( the "G31 + #5063 + G10 L2" pattern], called as a CAM post writes it: )
( G65 P9100 Z.. F.. W.. with the work system number as an argument. )
( Constructs: a post's safe-start line G90 G17 G40 G49 G80 G21, G91 G28 Z0, )
( G43 H20, G65 argument passing [Z=#26 F=#9 W=#23], G31 Z, #5063 with the )
( length offset in it [Fanuc: #5061.. are the tool reference point's], )
( #4111 [modal H], #11001/#10001 H geometry/wear by expression, #4003, )
( #[5203+20*W] work offset reads, G10 L2 P W Z, IF [..] GOTO, #3000 on a )
( miss [not reached here]. )
( Expected by hand: the ball centre [H20 = 150 on, G54 = machine] comes down )
( from Z-60 to Z-240 and touches the plate top -230 with its 1 mm radius at )
( -229; #5063 holds the gauge line there: -229 + 150 = -79. The face is )
( #5063 - H20 [150 + wear 0] - 1 = -230 [#101]; G54 Z becomes )
( 0 + [-230] = -230 [#5223], so G54 Z0 is the top face: the final G0 Z10. )
( puts the ball centre at machine -220 [work Z 10]. #102 = 1 [G54 kept]. )
G90 G17 G40 G49 G80 G21
G91 G28 Z0
G90 G54 G0 X10. Y20.
G43 H20 Z-60.
G65 P9100 Z-240. F200. W1.
#101 = #100
G0 Z10.
#102 = #4014 - 53
M30
O9100 (SURFACE TOUCH IN Z: Z END, F FEED, W WORK SYSTEM 1-6)
IF [#26 EQ #0] GOTO 91
IF [#23 EQ #0] GOTO 91
#30 = #4003 (G90 OR G91 ON ENTRY)
G90 G31 Z#26 F#9
IF [ABS[#5063 - #26] LT 0.001] GOTO 92
#100 = #5063 - #[11000 + #4111] - #[10000 + #4111] - 1.0 (THE FACE)
G10 L2 P#23 Z[#[5203 + 20 * #23] + #100]
G#30
M99
N91 #3000 = 91 (ARGUMENT MISSING)
N92 #3000 = 92 (PROBE DID NOT TOUCH)
M99
%
