%
O8 (O9811: NO SURFACE WITHIN Q STOPS WITH 3087 PROBE FAIL)
(Over the through bore, G54 X-0.123 Y-0.044, a touch down to the nominal)
(top face Z-0.37 with Q5 runs to Z-5.37 without a signal: alarm 3087)
(PROBE FAIL, and G54 Z, which S1 would have corrected, stays -229.5.)
N10 G21 G90 G17 G40 G49 G80 G54
N20 #550=1.
N30 G53 G0 Z0
N40 G43 H20 G0 X-0.123 Y-0.044
N50 G65 P9810 Z10. F3000.
N60 G65 P9811 Z-0.37 Q5. S1.
N70 M30
%
