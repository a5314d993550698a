(G84 right-hand tap, G99: in at F with the spindle CW, reversed at the bottom, out at F to R, CW again)
G21 G90 G17 G54
M3 S100
G0 X0 Y0 Z10.
G99 G84 X8. Z-10. R5. F125.
G80
M30
