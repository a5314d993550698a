(G68 with I and J but no K: P/S alarm 5044, B-62764EN format error)
(["When I, J, or K is not specified in a block with G68"].)
G21 G90 G17 G54 G0 X0 Y0 Z10.
G68 X0 Y0 Z0 I1. J0 R30.
G1 X20. F100.
M30
