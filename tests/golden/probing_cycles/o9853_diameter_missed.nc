%
O55 (O9853 B1: A TOOL FAR SMALLER THAN ITS D OFFSET MISSES THE SETTER)
(The setter and T1 of o9853_diameter: 10 across, its D1 set to a radius)
(of 20. B1 starts 20 + 5.998 + 5 = 30.998 out from the setter's axis and)
(touches at most Q10 past the expected side, to 15.998 out; the tool)
(would switch at 5 + 5.998 = 10.998: no touch, 3087 PROBE FAIL in the)
(touch, D1 left 20, #138 not written [set to -1 before].)
N10 G21 G90 G17 G40 G49 G80 G54
N20 #560=-300.002
N30 #561=-250.
N40 #562=-150.
N50 #566=5.998
N60 G10 L10 P1 R123.456
N70 G10 L12 P1 R20.
N80 #138=-1
N90 G53 G0 Z0
N100 T1 M6
N110 G65 P9853 T1. B1.
N120 M30
%
