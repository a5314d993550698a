(Strict mode and the protected-move idiom written compactly, as macro programmers)
(and the probing-cycle library write it: the operator GT between a bracket or a)
(digit and a number, with no spaces [IF[..]GT0.001], is the check for a miss as)
(much as the spaced form of strict_protected_move.nc: no skip_missed_read warning,)
(the run ends on the program's own alarm 3001 at the clamp, not strict_warning.)
G21G90G17G40G54
G43H20G0Z-150.
G0X-30.Y75.
G31Z-215.F2000.
IF[ABS[#5063-#5083+215.]GT0.001]THEN#3000=1(PATH OBSTRUCTED)
#101=#5063-#5083
G31X30.F2000.
IF[ABS[#5061-30.]GT.001]THEN#3000=1(PATH OBSTRUCTED)
G0Z-150.
M30
