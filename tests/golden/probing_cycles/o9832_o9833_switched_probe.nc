%
O13 (O9832 AND O9833: A RADIO PROBE SWITCHED ON AND OFF)
(The scene's probe is switched on by M59, off by M58 and signals 0.5 s)
(after it is on. #555 = 59, #556 = 58, #557 = 1 second of wait: O9832)
(switches it on, #101 = #554 = 1, the touch of the top face gives)
(#137 = -0.37; O9833 switches it off, #102 = #554 = 0. Without O9832)
(the touch would find no signal: the switched-off probe never signals.)
N10 G21 G90 G17 G40 G49 G80 G54
N20 #550=1.
N30 #555=59
N40 #556=58
N50 #557=1.
N60 G53 G0 Z0
N70 G43 H20 G0 X20. Y-20.
N80 G65 P9832
N90 #101=#554
N100 G65 P9810 Z5. F3000.
N110 G65 P9811 Z0 Q5.
N120 G65 P9810 Z50.
N130 G65 P9833
N140 #102=#554
N150 M30
%
