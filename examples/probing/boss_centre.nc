%
O5004 (BOSS CENTRE, 4 POINTS)
(Each side of the boss is touched from outside, 10 mm below its top; the)
(probe goes over the boss between the touches.)
(Results: #130 X centre, #131 Y centre, #132 diameter.)
#120 = 1.0 (effective ball radius, from calibration)
G21 G90 G17 G40 G54
G43 H20 G0 Z-200.
G0 X85. Y-40.3
G0 Z-219.87
G31 X60. F300.
#101 = #5061
G0 X85.
G0 Z-200.
G0 X36.
G0 Z-219.87
G31 X60. F300.
#102 = #5061
G0 X36.
G0 Z-200.
#130 = [#101 + #102] / 2
G0 X#130 Y-16.
G0 Z-219.87
G31 Y-40. F300.
#103 = #5062
G0 Y-16.
G0 Z-200.
G0 Y-65.
G0 Z-219.87
G31 Y-40. F300.
#104 = #5062
G0 Y-65.
G0 Z-200.
#131 = [#103 + #104] / 2
#132 = #103 - #104 - 2 * #120
G49 G53 G0 Z0
M30
%
