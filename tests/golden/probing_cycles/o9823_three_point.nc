%
O18 (O9823: THE BORE AND THE BOSS FROM THREE TOUCHES EACH)
(The bore, 40 mm at G54 X-0.123 Y-0.044, touched at 30, 150 and 270)
(degrees from the start X0 Y0: the three ball centres lie on a circle of)
(radius 19 about the bore's centre, so #101 = #135 = -0.123, #102 =)
(#136 = -0.044, #103 = #138 = 2 x [19 + 1] = 40, #104 = #145 =)
(0.261266148; S1: #5221 = -80.123, #5222 = 30.456. The boss, 30 mm at)
(machine X60.789 Y-40.321, is in the corrected G54 at X140.912)
(Y-70.777: touched at 45, 135 and 270 degrees from X140.9 Y-70.8 at Z10,)
(#135 = 140.912, #136 = -70.777, #138 = 2 x [16 - 1] = 30, #140 =)
(0.012, #141 = 0.023, #146 = #143 = 0.)
N10 G21 G90 G17 G40 G49 G80 G54
N20 #550=1.
N30 G53 G0 Z0
N40 G43 H20 G0 X0 Y0
N50 G65 P9810 Z-10. F3000.
N60 G65 P9823 A30. B150. C270. D40. Q5. S1.
N70 #101=#135
N80 #102=#136
N90 #103=#138
N100 #104=#145
N110 G65 P9810 Z50.
N120 G0 X140.9 Y-70.8
N130 G65 P9810 Z25.
N140 G65 P9823 A45. B135. C270. D30. Z10. Q5. R5.
N150 G65 P9810 Z50.
N160 M30
%
