(G41 round the outside of a 20 x 20 square, D1 = 5: start-up of type A ends perpendicular to the first side, X5 Y10; the plunge between start-up and contour is looked past; the 90-degree outer corners end at the intersections X5 Y35, X35 Y35, X35 Y5; the cancel ends perpendicular to the last side, X10 Y5)
G21 G90 G17 G40 G49 G80
G10 L12 P1 R5.
G0 X0 Y0 Z5.
G41 D1 X10. Y10.
Z-2.
G1 Y30. F300.
X30.
Y10.
X10.
G40 X0 Y0
G0 Z5.
M30
