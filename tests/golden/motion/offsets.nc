(Work offsets from the machine file, G52 local shift, G43 tool length, G53 machine moves)
G21 G90 G17
G55 G0 X0 Y0
G52 X10. Y-5.
G0 X0 Y0
G52 X0 Y0
G43 H1 Z0
G53 G0 Z0
G49 G0 Z0
G54 G91 G0 X1. Y1.
M30
