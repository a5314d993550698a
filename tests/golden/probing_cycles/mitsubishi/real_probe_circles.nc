%
O23 (O9819 AND O9823 WITH A REAL PROBE: WITHIN THE LATCH BOUND)
(real_probe_circles.scene.toml: 4 um pre-travel, 3-lobed lobing of 2)
(um, 0.5 um 1 sigma scatter, as real_probe_cycles. O9802 takes #550 from)
(the 40 mm bore: #111 = 0.995 within 1.5 um. Each touch then reads its)
(wall within the lobing + 5 sigma = 4.5 um, as in real_probe_cycles:)
(a feature's centre from O9814-style passes within 4.5 um, its size within)
(9 um; a pitch circle's centre [the mean of the features' centres] within)
(4.5 um, its diameter [twice the mean distance of the features' centres)
(from it] within 2 x 9 = 18 um, the first feature's angle within)
(ATAN[9 um / 25 mm] = 0.021 degree. Three touches 120 degrees apart:)
(the centre moves by 2/3 of the sum of the touches' radial errors along)
(their directions, at most 2/3 x 2 x 4.5 = 6 um; the size by twice their)
(mean, 9 um. The ideal values are those of o9819_pitch_circle, of)
(o9819_bosses and of the bore [G54 X-0.123 Y-0.044, 40 across].)
N10 G21 G90 G17 G40 G49 G80 G54
N20 G53 G0 Z0
N30 G43 H20 G0 X0 Y0
N40 G65 P9810 Z-10. F3000.
N50 G65 P9802 D40. Q5.
N60 #111=#550
N70 G65 P9823 A0. B120. C240. D40. Q5.
N80 #112=#135
N90 #113=#136
N100 #114=#138
N110 G65 P9810 Z50.
N120 G0 X100. Y-60.5
N130 G65 P9810 Z5.
N140 G65 P9819 A45. B4. C60. D10. K-5. Q5.
N150 #101=#135
N160 #102=#136
N170 #103=#138
N180 #104=#139
N190 #105=#142
N200 G65 P9810 Z50.
N210 G0 X150. Y-60.
N220 G65 P9810 Z15.
N230 G65 P9819 A18. B5. C50. D12. Z3. Q5. R5.
N240 #106=#135
N250 #107=#136
N260 #108=#138
N270 #109=#139
N280 #110=#142
N290 G65 P9810 X150. Y-35.
N300 G65 P9823 A0. B120. C240. D12. Z3. Q5. R5.
N310 #115=#135
N320 #116=#136
N330 #117=#138
N340 G65 P9810 Z50.
N350 M30
%
