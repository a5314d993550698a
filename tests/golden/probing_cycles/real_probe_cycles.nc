%
O14 (THE CYCLES WITH A REAL PROBE: WITHIN THE LATCH BOUND)
(part_real.scene.toml: 4 um pre-travel, 3-lobed lobing of 2 um, 0.5 um)
(1 sigma scatter. O9801 first calibrates H20 on the top face, G54)
(Z-0.37, which takes the Z pre-travel into H20; O9802 then takes the)
(ball's effective radius #550 from the 40 mm bore as a ring gauge: 1)
(less the 4 um pre-travel less the mean lobing of its touches, 1 um,)
(#117 = 0.995 within 1.5 um. Then)
(each wall reads within the lobing + 5 sigma = 4.5 um of its place: a)
(centre or a corner's wall within 4.5 um, a size within 9 um, the top)
(face within 2 x 5 sigma = 5 um, of the ideal probe's values in the)
(other cases.)
N10 G21 G90 G17 G40 G49 G80 G54
N30 G53 G0 Z0
N40 G43 H20 G0 X20. Y-20.
N50 G65 P9810 Z5. F3000.
N60 G65 P9801 Z-0.37 T20 Q5.
N70 #112=#142 (H20's correction: the pre-travel, about 0.004)
N80 G65 P9811 Z0 Q5.
N90 #101=#137
N100 G65 P9810 Z50.
N110 G0 X0 Y0
N120 G65 P9810 Z-10.
N125 G65 P9802 D40. Q5.
N127 #117=#550
N130 G65 P9814 D40. Q5.
N140 #102=#135
N150 #103=#136
N160 #104=#138
N170 G65 P9810 Z50.
N180 G0 X140.8 Y-70.8
N190 G65 P9810 Z25.
N200 G65 P9814 D30. Z10. Q5. R5.
N210 #105=#135
N220 #106=#136
N230 #107=#138
N240 G65 P9810 Z50.
N250 G0 X65. Y-90.4
N260 G65 P9810 Z-10.
N270 G65 P9812 X50.6 Q5.
N280 #108=#135
N290 #109=#138
N300 G65 P9810 Z50.
N310 G0 X186.5 Y20.
N320 G65 P9810 Z25.
N330 G65 P9812 X12.5 Z10. Q5. R5.
N340 #110=#135
N350 #111=#138
N360 G65 P9810 Z50.
N370 G0 X85. Y-75.
N380 G65 P9810 Z-10.
N390 G65 P9815 X90.35 Y-70.5 Q5.
N400 #113=#135
N410 #114=#136
N420 G65 P9810 Z50.
N430 G0 X235. Y75.
N440 G65 P9810 Z-5.
N450 G65 P9816 X230. Y69.5 Q5.
N460 #115=#135
N470 #116=#136
N480 G65 P9810 Z50.
N490 M30
%
