(G41, D1 = 6, along a line, a tangent half circle of R20 in G02 and a line: tangent joins end perpendicular, X-26 Y0 and X26 Y0; the G02 arc on the left of its travel runs on R26 about the same centre)
G21 G90 G17 G40
G10 L12 P1 R6.
G0 X-20. Y-50. Z-2.
G41 D1 X-20. Y-30.
G1 Y0 F400.
G2 X20. Y0 R20.
G1 Y-30.
G40 X0 Y-50.
M30
