(G37: no signal up to epsilon past the measuring position: PS0080)
G21 G90 G17 G54
G43 H1 G0 Z50.
G37 Z0
M30
