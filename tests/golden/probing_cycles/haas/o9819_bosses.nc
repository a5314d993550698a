%
O22 (O9819 AND O9823: BOSSES, FROM OUTSIDE)
(o9819_bosses.scene.toml: five bosses 11.98 across [D12. nominal] on a)
(circle 50 across, its centre at G54 X149.93 Y-59.96 [nominal X150)
(Y-60], turned 3 degrees [the first boss at 21, nominal 18]; their tops)
(at G54 Z7.63, each touched at Z3. from R5. outside, the probe moving)
(between them at Z15.)
(First O9823 on the second boss, nominal at 90 degrees: X150 Y-35, true)
(at 93 degrees: X149.93 + 25 COS93 = 148.621601094, Y-59.96 + 25 SIN93)
(= -34.994261631; touched at 0, 120, 240 degrees from its nominal)
(centre, the three ball centres on a circle of radius 5.99 + 1 about)
(it: #101 = 148.621601094, #102 = -34.994261631, #103 = 2 x [6.99 - 1])
(= 11.98, #104 = #143 = #146 = -0.02 [a boss smaller: less metal].)
(Then O9819 with S1: #135 = 149.93, #136 = -59.96, #138 = 11.98, #139)
(= 21, #140 = -0.07, #141 = 0.04, #142 = 0, #143 = -0.02, #144 = 3,)
(#145 = 2 SQRT[0.07^2 + 0.04^2] = 0.161245155, #147 = 5, #148 = 0;)
(G54 #5221 = -80 - 0.07 = -80.07, #5222 = 30.5 + 0.04 = 30.54.)
N10 G21 G90 G17 G40 G49 G80 G54
N20 #550=1.
N30 G53 G0 Z0
N40 G43 H20 G0 X150. Y-35.
N50 G65 P9810 Z15. F3000.
N60 G65 P9823 A0. B120. C240. D12. Z3. Q5. R5.
N70 #101=#135
N80 #102=#136
N90 #103=#138
N100 #104=#146
N110 G65 P9810 X150. Y-60.
N120 G65 P9819 A18. B5. C50. D12. Z3. Q5. R5. S1.
N130 G65 P9810 Z50.
N140 M30
%
