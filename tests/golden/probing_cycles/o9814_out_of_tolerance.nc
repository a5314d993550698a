%
O9 (O9814 H: A DIAMETER OUT OF ITS TOLERANCE STOPS WITH 3088)
(The 40 mm bore called as D40.5 H0.1: #143 = 40 - 40.5 = -0.5, larger)
(than 0.1: #148 = 1 and alarm 3088 OUT OF TOLERANCE; the results are)
(stored, #138 = 40, and G54, which S1 would have corrected, is left:)
(#5221 = -80, #5222 = 30.5.)
N10 G21 G90 G17 G40 G49 G80 G54
N20 #550=1.
N30 G53 G0 Z0
N40 G43 H20 G0 X0 Y0
N50 G65 P9810 Z-10. F3000.
N60 G65 P9814 D40.5 Q5. S1. H0.1
N70 M30
%
