%
O1012 (HAAS: A DOUBLE TOUCH LOOPED BY M99 P INSIDE A SUBPROGRAM)
( Compatibility: in the style of the Haas macro programming examples of )
( the mill manual [96-8000, Macros, "Conditional expressions": N50 M99 P10 )
( branches to N10 of the subprogram it is in and "does not return control )
( to the calling subroutine"], a touch repeated slow after fast as probing )
( subprograms do; on a Fanuc control the same M99 P20 would return to N20 )
( of the caller. )
( Constructs: M98 P2000 to a program in the same file, M99 P20 looping )
( within it, IF [..] GOTO out of the loop, M99 returning to the block after )
( M98, indirect #[110 + #101], the feed of each pass from a table. )
( Expected by hand: G54 = X30 Y0 Z-225; both passes touch the plate's top )
( [-229.87] with the ball centre at work -3.87: #111 = #112 = -3.87, #101 )
( = 2 passes, and the main program goes on after M98: #120 = 1. )
G00 G17 G40 G49 G80 G90 G94 G97
G21
G10 L2 P1 X30. Y0. Z-225.
T20 M06
G54 G00 X0. Y0.
G43 H20 Z-1.
#115 = 600. (fast)
#116 = 60. (slow)
M98 P2000
#120 = 1
G00 Z50.
G49 G53 G00 Z0.
M30
O2000 (TOUCH, BACK OFF 2 MM, TOUCH AGAIN SLOWER)
#101 = 0
N20 #101 = #101 + 1
G31 Z-10. F#[114 + #101]
#[110 + #101] = #5063 - #5083
G00 Z[#[110 + #101] + 2.]
IF [#101 GE 2] GOTO 40
M99 P20
N40 M99
%
