(G76: dwell P300 at the bottom, oriented stop, shift Q0.5 in -X, parameter 5101 RD1 = 1, rapid out, shift back, spindle on again)
G21 G90 G17 G54 F80.
M3 S500
G0 X20. Y10. Z30.
G98 G76 Z-15. R3. Q0.5 P300
G80
M30
