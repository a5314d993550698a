%
O16 (O9811: A TOUCH THAT STARTS WITH THE STYLUS DEFLECTED STOPS WITH 3092)
(Probe protection off, -p 90020=0: a plain G01 pushes the 1 mm ball 0.5)
(into the plate's right face, G54 X230: the probe signals before O9811)
(starts. Its first skip latches where it starts, X230.5, and the cycle)
(stops with 3092 PROBE OPEN: no surface is taken from it, #135 stays)
(vacant and G54 X, which S1 would have corrected, stays -80.)
N10 G21 G90 G17 G40 G49 G80 G54
N20 #550=1.
N30 G53 G0 Z0
N40 G43 H20 G0 X235. Y0
N50 G65 P9810 Z-5. F3000.
N60 G01 X230.5 F200.
N70 G65 P9811 X229.8 Q5. S1.
N80 M30
%
