%
O9810 (PROTECTED POSITIONING - OWN MACRO FOR THE COMPATIBILITY PROGRAMS)
(In the style of the call interface G65 P9810 X.. Y.. Z.. F.. that posts)
(write; our own text. X Y Z: the target, work coordinates of the probe's)
(ball centre [G43 on]; F: the feed, default 3000. The move is a G31: a)
(stop short of the target means the probe touched something on the way,)
(alarm 91 PATH OBSTRUCTED [#3000].)
IF [#9 NE #0] GOTO 1
#9 = 3000.
N1 G31 X#24 Y#25 Z#26 F#9
IF [#24 EQ #0] GOTO 2
IF [ABS[#5061 - #24] GT 0.005] GOTO 9
N2 IF [#25 EQ #0] GOTO 3
IF [ABS[#5062 - #25] GT 0.005] GOTO 9
N3 IF [#26 EQ #0] GOTO 4
IF [ABS[#5063 - #5083 - #26] GT 0.005] GOTO 9
N4 M99
N9 #3000 = 91 (PATH OBSTRUCTED)
M99
%
