(G41 inside a pocket corner, D1 = 4: the inner corner of 90 degrees ends at the intersection of the offset lines, X16 Y4; with two blocks without a plane move - G4 and M8 - after the second side, its end is perpendicular, X16 Y20, as the control does)
G21 G90 G17 G40
G10 L12 P1 R4.
G0 X0 Y-10. Z0
G41 D1 X0 Y0
G1 X20. F300.
Y20.
G4 P100
M8
X0
G40 Y-10.
M30
