%
O21 (O9819: FOUR HOLES ON A PITCH CIRCLE, THE CIRCLE 2 DEGREES TURNED)
(The circle's centre is at machine X20.05 Y-29.97, in G54 [X-80 Y30.5])
(X100.05 Y-60.47; 60 across, holes 10 across, the first at 47 degrees.)
(Called as A45 from its nominal centre X100 Y-60.5: #135 = 100.05,)
(#136 = -60.47, #138 = 10, #139 = 47, #140 = 0.05, #141 = 0.03,)
(#142 = 0, #143 = 0, #144 = 2, #145 = 2 SQRT[0.05^2 + 0.03^2] =)
(0.116619038, #147 = 4; S1: #5221 = -79.95, #5222 = 30.53. The holes)
(are measured 5 mm under the top, K-5.)
N10 G21 G90 G17 G40 G49 G80 G54
N20 #550=1.
N30 G53 G0 Z0
N40 G43 H20 G0 X100. Y-60.5
N50 G65 P9810 Z5. F3000.
N60 G65 P9819 A45. B4. C60. D10. K-5. Q5. S1.
N70 G65 P9810 Z50.
N80 M30
%
