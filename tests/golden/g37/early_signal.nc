(G37: the signal comes 1.5 mm before the measuring position, outside epsilon = 1 mm: PS0080)
G21 G90 G17 G54
G43 H1 G0 Z50.
G37 Z0
M30
