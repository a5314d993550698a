%
O17 (O9843: THE ANGLES OF A BLOCK'S FACES, 2 DEGREES OFF SQUARE)
(The block's left face runs at 90 + 2 degrees, its front face at 2: two)
(touches D apart on a straight face are offset from it alike, so the)
(line through them has the face's angle exactly, whatever the ball:)
(X face, D30: #101 = #139 = 92, #102 = #144 = 92 - 90 = 2. Y face, D40,)
(A left out, 0: #139 = 2, #144 = 2; with B1. that is out of tolerance:)
(#148 = 4 and alarm 3094 ANGLE OUT OF TOL. G54: X-80 Y30.5 Z-229.5.)
(The Y face's first touch, at machine X-80: the face is at machine)
(Y-50 + 20 TAN2 = -49.30158461, the ball's centre 1 / COS2 below it,)
(the surface read its centre + 1: #136 = -50 + 20 TAN2 - 1 / COS2 + 1 -)
(30.5 = -79.802194154, #141 = #136 - -79.8 = -0.002194154.)
N10 G21 G90 G17 G40 G49 G80 G54
N20 #550=1.
N30 G53 G0 Z0
N40 G43 H20 G0 X-30. Y-70.5
N50 G65 P9810 Z0 F3000.
N60 G65 P9843 X-20.35 D30. Q5.
N70 #101=#139
N80 #102=#144
N90 G65 P9810 Z30.
N100 G0 Y-90.
N110 G0 X0
N120 G65 P9810 Z0
N130 G65 P9843 Y-79.8 D40. Q5. B1.
N140 M30
%
