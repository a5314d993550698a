%
O0001 (SKIPNC DEMO - FIND THE TOP OF A PART WITH A TOUCH PROBE)
(The part's top face is 23.8 mm below machine zero; the probe is on X0.4.)
N10 G21 G90 G17 G40 G49 G54
N20 G0 X0 Y0 Z0
(Fast touch: find the surface)
N30 G31 Z-40. F600.
N40 #100 = #5063 (first touch, work Z)
N50 G91 G0 Z2.
(Slow touch: measure it)
N60 G90 G31 Z-40. F60.
N70 #101 = #5063 (second touch, work Z)
N80 G91 G0 Z5.
N90 G90
(Set G54 Z so that the part top is Z0)
N100 G10 L2 P1 Z[#5223 + #101]
N110 #102 = #101 - #100 (difference between the touches)
N120 (MSG, G54 Z SET FROM THE SECOND TOUCH)
N130 G0 Z10.
N140 M30
%
