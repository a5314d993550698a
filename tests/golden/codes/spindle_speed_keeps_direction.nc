(A new S word alone changes the speed, not the direction: the spindle)
(started by M03 still turns CW, and M04 with S turns it CCW at the new)
(speed. The tool cuts a [stock] while the spindle turns.)
G21 G90 G54
S1000 M03
G1 X10. F500.
S2000
G1 X20.
S1500 M04
M05
S800
M30
