%
O3 (O9812 WITHOUT Z: THE POCKET ACROSS X, THEN ACROSS Y)
(The pocket: machine X-40.25..10.35, Y-80..-40, floor Z-249.87; in G54)
([X-80 Y30.5 Z-229.5] X39.75..90.35, Y-110.5..-70.5: 50.6 by 40, centre)
(X65.05 Y-90.5. Started at X65 Y-90.4, 10 mm under the top face:)
(X pass: #135 = 65.05, #138 = 50.6, #140 = 65.05 - 65 = 0.05, #143 = 0,)
(#145 = 0.1, #146 = -#143 = 0; S1: G54 X #5221 = -80 + 0.05 = -79.95.)
(Y pass, from Y-90.4 of the corrected G54, the same place on Y: #136 =)
(-90.5, #138 = 40, #141 = -0.1; no S: G54 Y #5222 stays 30.5.)
N10 G21 G90 G17 G40 G49 G80 G54
N20 #550=1.
N30 G53 G0 Z0
N40 G43 H20 G0 X65. Y-90.4
N50 G65 P9810 Z-10. F3000.
N60 G65 P9812 X50.6 Q5. S1.
N70 #101=#135
N80 #102=#138
N90 #103=#140
N100 #104=#145
N110 G65 P9812 Y40. Q5.
N120 G65 P9810 Z50.
N130 M30
%
