%
O25 (O9816 AND O9815 WITH I J: CORNERS OF A BLOCK 2 DEGREES OFF SQUARE)
(o9815_o9816_angles.scene.toml: the block turned 2 degrees about its)
(front-left corner, G54 X0 Y-50, a pocket in it from frame X20 Y15.)
(1. O9816 X0. Y-50. I10. J10. from X-6 Y-56: the left face touched at)
(Y-44 and Y-34, the front face at X6 and X16. Two touches on a straight)
(face are offset from it alike, so each face is the line through them)
(moved by the ball's radius along its normal: the corner is exact,)
(#101 = #135 = 0, #102 = #136 = -50; #103 = #139 = 92 [the left face)
(from +X], #104 = #144 = 2, #105 = #142 = 2 [the front face], #106 =)
(#143 = 2. 2. O9815 X20. Y-35. I10. J10. S1. from X26 Y-29: the)
(pocket's corner, nominal at the square X20 Y-35, is at 20 COS2 - 15)
(SIN2 = 19.46432409, -50 + 20 SIN2 + 15 COS2 = -34.311147661: #140 =)
(-0.53567591, #141 = 0.688852339, #145 = 2 SQRT[#140^2 + #141^2] =)
(1.745240644, #139 = 92, #144 = 2; S1: #5221 = -80 - 0.53567591 =)
(-80.53567591, #5222 = 30.5 + 0.688852339 = 31.188852339; the results)
(#107-#113 keep them. 3. O9816 again with B1. in the corrected G54,)
(where the corner, machine X-80 Y-19.5, is at X-80 + 80.53567591 =)
(0.53567591, Y-19.5 - 31.188852339 = -50.688852339 [#135 #136], #140 =)
(0.53567591, #141 = -0.688852339: #144 = 2 is out of B: #148 = 4, alarm)
(3094 ANGLE OUT OF)
(TOL, the results stored and copied [#194 = 2].)
N10 G21 G90 G17 G40 G49 G80 G54
N20 #550=1.
N30 G53 G0 Z0
N40 G43 H20 G0 X-6. Y-56.
N50 G65 P9810 Z-5. F3000.
N60 G65 P9816 X0. Y-50. I10. J10. Q5.
N70 #101=#135
N80 #102=#136
N90 #103=#139
N100 #104=#144
N110 #105=#142
N120 #106=#143
N130 G65 P9810 Z10.
N140 G0 X26. Y-29.
N150 G65 P9810 Z-5.
N160 G65 P9815 X20. Y-35. I10. J10. Q5. S1.
N162 #107=#135
N163 #108=#136
N164 #109=#140
N165 #110=#141
N166 #111=#145
N167 #112=#139
N168 #113=#144
N170 G65 P9810 Z10.
N180 G0 X-6. Y-56.
N190 G65 P9810 Z-5.
N200 G65 P9816 X0. Y-50. I10. J10. Q5. B1.
N210 M30
%
