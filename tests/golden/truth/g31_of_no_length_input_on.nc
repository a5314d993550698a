(A G31 of no length with the input on is a detected signal: K1 asks for an alarm)
(when no signal comes, and none is raised; the report says triggered, ended by signal)
G21 G90 G54
G0 X0 Y0 Z0
G31 Z0 F100. K1
M30
