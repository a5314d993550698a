(G37.1 is not a machining centre code of the Fanuc dialect: an improper G)
(code [PS0010], as before Mitsubishi's G37.1 was named)
G21 G90 G17 G54
G43 H1 G0 Z50.
G37.1 Z0
M30
