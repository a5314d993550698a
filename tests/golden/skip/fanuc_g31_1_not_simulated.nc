(G31.1 is not a skip code of the Fanuc dialect here: the alarm says it is not simulated)
G21 G90 G54 G31.1 Z-50. F100.
M30
