%
O22 (O9802: THE BALL'S EFFECTIVE RADIUS ON A RING GAUGE, THEN A BOSS)
(The plate's 40 mm bore serves as the ring gauge, at G54 X-0.123)
(Y-0.044. From X0 Y0, 10 mm down, O9802 D40. finds the ball's centres)
(38 mm apart across it: #550 = [40 - 38] / 2 = 1, #101 = #138 = 2,)
(#135 = -0.123, #136 = -0.044. The boss measured with it: #102 = #138)
(= 30. #550 was vacant before: no other setting is needed.)
N10 G21 G90 G17 G40 G49 G80 G54
N20 G53 G0 Z0
N30 G43 H20 G0 X0 Y0
N40 G65 P9810 Z-10. F3000.
N50 G65 P9802 D40. Q5.
N60 #101=#138
N70 #103=#135
N80 #104=#136
N90 G65 P9810 Z50.
N100 G0 X140.8 Y-70.8
N110 G65 P9810 Z25.
N120 G65 P9814 D30. Z10. Q5. R5.
N130 #102=#138
N140 G65 P9810 Z50.
N150 M30
%
