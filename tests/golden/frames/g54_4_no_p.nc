(G54.4 without P: alarm bad_value at the G54.4 word, nothing moved.)
G21 G90 G17 G54 G0 X0 Y0 Z10.
G54.4
G1 X20. F100.
M30
