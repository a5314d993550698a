(Strict mode people can use: the protected-move idiom under --strict. A G31 through)
(free air that misses is the expected outcome; the program checks for a trip by)
(comparing #5063 with the target, then reads the value again after the check: no)
(skip_missed_read warning, so --strict runs on. The second move meets the clamp:)
(the program's own alarm 3001, not strict_warning.)
G21 G90 G17 G40 G54
G43 H20 G0 Z-150.
G0 X-30. Y75.
G31 Z-215. F2000.
IF [ABS[#5063 - #5083 + 215.] GT 0.001] THEN #3000 = 1 (PATH OBSTRUCTED)
#101 = #5063 - #5083
G31 X30. F2000.
IF [ABS[#5061 - 30.] GT 0.001] THEN #3000 = 1 (PATH OBSTRUCTED)
G0 Z-150.
M30
