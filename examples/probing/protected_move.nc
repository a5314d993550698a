%
O5005 (PROTECTED POSITIONING)
(Each move near the part is a G31 move at a safe feed: if the probe)
(switches, the move stops and the program stops with alarm 3001 instead)
(of pushing on. The move across X meets the clamp.)
G21 G90 G17 G40 G54
G43 H20 G0 Z-150.
G0 X-30. Y75.
G31 Z-215. F2000. (down beside the clamp: clear)
IF [ABS[#5063 - #5083 + 215.] GT 0.001] THEN #3000 = 1 (PATH OBSTRUCTED)
G31 X30. F2000. (across: the clamp is in the way)
IF [ABS[#5061 - 30.] GT 0.001] THEN #3000 = 1 (PATH OBSTRUCTED)
G0 Z-150.
G49 G53 G0 Z0
M30
%
