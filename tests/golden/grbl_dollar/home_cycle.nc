( grbl's $X and $H with $22=1 [Grbl v1.1 Commands]: the run starts locked )
( [the message grbl prints at reset], $X unlocks with its caution, and $H )
( homes Z, then X and Y, each to its switch at the top of its travel )
( [machine 0 on grbl3] and back by $27 = 1 mm: the machine ends at )
( -1,-1,-1, as grbl's default build sets it. After $H the G54 offset G10 )
( L20 sets is from there: G54 X = -1 - 5 = -6. )
$X
G53 G0 X-100 Y-100 Z-50
$H
G10 L20 P1 X5 Y0 Z0
$#
M2
