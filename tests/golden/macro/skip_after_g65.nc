(The skip position #5061.. keeps its value after the macro that moved)
(returns; the macro's local copy is gone)
G21 G90 G54
G0 X0 Y0 Z0
G65 P7700 F100.
#100=#5063
#101=#1
M30
O7700
G31 Z-10. F#9
#1=#5063
M99
