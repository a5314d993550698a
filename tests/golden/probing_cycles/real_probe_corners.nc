%
O26 (THE CORNERS WITH I J AND A REAL PROBE: WITHIN THE LATCH BOUND)
(real_probe_corners.scene.toml: the block and pocket of)
(o9815_o9816_angles, 4 um pre-travel, 3-lobed lobing of 2 um, 0.5 um 1)
(sigma scatter. O9802 on the 30 mm ring: #111 = #550 = 0.995 within 1.5)
(um. Each touch then reads its wall within the lobing + 5 sigma = 4.5)
(um [real_probe_cycles]. A face's angle from two touches 10 mm apart:)
(within ATAN[9 um / 10 mm] = 0.052 degree. The corner: each face's line)
(is off by at most 4.5 um at its first touch, 6 mm from the corner, and)
(turned by at most 9 um / 10 mm, so off by at most 4.5 + 0.6 x 9 = 9.9 um)
(at the corner [outer: the touches at 6 and 16 mm past it; inner: at 6)
(and 16 mm from the other wall]; the corner, where the lines meet at 90)
(degrees, within 9.9 um in X and in Y. Ideal values: o9815_o9816_angles.)
N10 G21 G90 G17 G40 G49 G80 G54
N20 G53 G0 Z0
N30 G43 H20 G0 X-50. Y-110.5
N40 G65 P9810 Z-5. F3000.
N50 G65 P9802 D30. Q5.
N60 #111=#550
N70 G65 P9810 Z10.
N80 G0 X-6. Y-56.
N90 G65 P9810 Z-5.
N100 G65 P9816 X0. Y-50. I10. J10. Q5.
N110 #101=#135
N120 #102=#136
N130 #103=#144
N140 #104=#143
N150 G65 P9810 Z10.
N160 G0 X26. Y-29.
N170 G65 P9810 Z-5.
N180 G65 P9815 X20. Y-35. I10. J10. Q5.
N190 #105=#135
N200 #106=#136
N210 #107=#144
N220 #108=#143
N230 G65 P9810 Z10.
N240 M30
%
