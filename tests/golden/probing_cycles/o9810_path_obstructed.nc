%
O7 (O9810: A PROTECTED MOVE THAT MEETS THE CLAMP STOPS WITH 3086)
(The clamp: machine X-10..10, Y60..90, top Z-190; in G54 X70..90,)
(Y29.5..59.5, top Z39.5. At Y40 Z30 the move to X100 meets its X70 face)
(with the 1 mm ball: the skip stores X69 and the program stops at once)
(with #3000 = 86, alarm 3086 PATH OBSTRUCTED, at O9810's block N86.)
(The move to Z30 before it, F omitted, runs at the F2000 kept in #551.)
N10 G21 G90 G17 G40 G49 G80 G54
N20 #550=1.
N30 G53 G0 Z0
N40 G43 H20 G0 X50. Y40.
N50 G65 P9810 Z50. F2000.
N60 G65 P9810 Z30.
N70 G65 P9810 X100.
N80 M30
%
