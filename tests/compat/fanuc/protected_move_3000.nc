%
O1003 (PROTECTED POSITIONING, PATH OBSTRUCTED ALARM)
( Compatibility: in the style of the Renishaw-type "protected positioning" )
( macro that Fanuc CAM posts call before every probing move [G65 P9810 X.. )
( Y.. Z.. F..], as Fusion and Mastercam Fanuc posts write it, and of the )
( #3000 error traps of cncci.com/post/generating-alarms-for-dangerous-situations. )
( Constructs: G65 P9810 with X Y F arguments, vacant tests [#24 EQ #0], )
( G31 X Y as a guarded move, the stored position of an untouched G31 [its end )
( point], ABS[], IF [..] GOTO, #3000 = 86 with its message: alarm 3086. )
( Expected by hand [G54 = machine, ball radius 1, ball centre at Z-210]: the )
( first move X20 Y0 reaches its end untouched [#5061 = 20, #100 = 20]; the )
( second, to X80, meets the clamp face X40 at ball centre X39: #5061 = 39 is )
( 41 short of 80, so the macro raises #3000 = 86 [PATH OBSTRUCTED]: alarm )
( 3086 at line 34; the machine rests past X39 by up to one servo period at )
( F3000 [0.05 mm]. )
G90 G17 G40 G49 G80 G21
G91 G28 Z0
G90 G54 G0 X0 Y0
G43 H20 Z-210.
G65 P9810 X20. Y0 F3000.
#100 = #5061
G65 P9810 X80. Y0 F3000.
#101 = #5061 (NOT REACHED)
M30
O9810 (PROTECTED POSITIONING: X Y END, F FEED)
IF [#24 EQ #0] THEN #24 = #5041
IF [#25 EQ #0] THEN #25 = #5042
IF [#9 EQ #0] THEN #9 = 1000.
G90 G31 X#24 Y#25 F#9
IF [ABS[#5061 - #24] GT 0.005] GOTO 86
IF [ABS[#5062 - #25] GT 0.005] GOTO 86
M99
N86
#3000 = 86 (PATH OBSTRUCTED)
M99
%
