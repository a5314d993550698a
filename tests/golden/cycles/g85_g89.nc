(G85 feeds out to R; G89 dwells P500 at the bottom and feeds out; G98 then rapids to the initial level)
G21 G90 G17 G54 F60.
G0 X0 Y0 Z5.
G98 G85 X1. Z-3. R1.
G89 X2. P500
G80
M30
