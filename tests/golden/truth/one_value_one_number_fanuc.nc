(One value, one number: a touch between two increments. The report's)
(skips[].position is the very number the program reads from #5061..: here the)
(latch as computed, -1.5728059, in both: fanuc stores it unrounded)
(skip_position_increment = false, docs/position-variables.md.)
G21 G90 G54
G0 X0 Y0 Z0
G31 Z-10. F100.
#100 = #5063
M30
