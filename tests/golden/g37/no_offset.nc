(G37 without an active tool length offset: PS0081)
G21 G90 G17 G54
G0 Z50.
G37 Z0
M30
