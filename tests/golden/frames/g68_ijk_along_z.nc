%
(G68 X Y Z I J K R, the 3-D form CAM posts write after an angle probing)
(cycle: with the vector I0 J0 K1 it is the G17 rotation about X Y, Z is)
(not used; K-1 turns the other way. Centre X10 Y5, 90 degrees:)
(X20 Y5 is 10 along +X from the centre, turned to 10 along +Y: X10 Y15;)
(with K-1 turned to 10 along -Y: X10 Y-5. Without a decimal point K1 is)
(0.001, still along +Z: X20 Y5 to X10 Y15 again.)
N1 G21 G90 G17 G54 G0 X0 Y0 Z10.
N2 G68 X10. Y5. Z0 I0 J0 K1. R90.
N3 G1 X20. Y5. F100.
N4 G69
N5 G68 X10. Y5. Z-3. I0 J0 K-1. R90.
N6 G1 X20. Y5.
N7 G69
N8 G68 X10. Y5. Z0 I0 J0 K1 R90.
N9 G1 X20. Y5.
N10 G69
N11 M30
%
