(G68 with I J K but no R: P/S alarm 5044, B-62764EN "Three-dimensional)
(coordinate conversion", format error; at the G68 word, nothing moved.)
G21 G90 G17 G54 G0 X0 Y0 Z10.
G68 X0 Y0 Z0 I1. J0 K0
G1 X20. F100.
M30
