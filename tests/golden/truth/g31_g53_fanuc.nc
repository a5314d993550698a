(The G31/G53 sentence of docs/skip-dialects.md, tried on fanuc: the skip move of this)
(control, G31, with G53 in its block.)
G21 G90 G54
G0 X0 Y0 Z0
G31 G53 Z-10. F100.
M30
