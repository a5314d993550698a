%
O1 (O9811 Z: THE PLATE'S TOP FACE SETS G54 Z)
(The top face is at machine Z-229.87, G54 Z is -229.5: the face is at work)
(Z-0.37, so #137 = -0.37, #142 = -0.37 - 0 = -0.37, #145 = 0.74, the)
(touch went down, met the face 0.37 late: metal condition #146 = -0.37.)
(S1 adds the error to G54 Z: #5223 = -229.5 - 0.37 = -229.87.)
N10 G21 G90 G17 G40 G49 G80 G54
N20 #550=1. (the ball's radius)
N30 G53 G0 Z0
N40 G43 H20 G0 X20. Y-20. (over the plate, clear of its features)
N50 G65 P9810 Z5. F3000.
N60 G65 P9811 Z0 Q5. S1.
N70 #100=#5003 (back at the start, Z5 of the old G54: 5.37 in the new one)
N80 G65 P9810 Z50.
N90 M30
%
