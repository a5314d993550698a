(G54.4 P8: the data sets are 0 to 7 [skipnc's reading, docs/probing-cycles.md]:)
(alarm bad_value at the P word, nothing moved.)
G21 G90 G17 G54 G0 X0 Y0 Z10.
G54.4 P8
G1 X20. F100.
M30
