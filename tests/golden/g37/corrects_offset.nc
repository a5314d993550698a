(G37 Z0 with G43 H1 = 100 mm: the measuring position is machine Z100. Rapid to gamma = 10 mm before it, Z110, then at 100 mm/min; the tool is 0.3 mm longer, so the signal ZAE X4.2 comes at Z100.3 and 0.3 is added to H1, its wear #10001. G0 Z50 then goes to 50 + 100.3)
G21 G90 G17 G54
G43 H1 G0 Z50.
G37 Z0
#101 = #10001
G0 Z50.
#103 = #5023
M30
