%
O5003 (BORE CENTRE, 4 POINTS)
(From the bore's nominal position, 10 mm below the top face: X+ and X-,)
(the X centre; at the X centre, Y+ and Y-, the Y centre and the diameter.)
(Results: #130 X centre, #131 Y centre, #132 diameter.)
#120 = 1.0 (effective ball radius, from calibration)
G21 G90 G17 G40 G54
G43 H20 G0 Z-200.
G0 X-80. Y30.5 (the drawing's position)
G0 Z-239.87
G31 X-50. F300.
#101 = #5061
G0 X-80.
G31 X-110. F300.
#102 = #5061
#130 = [#101 + #102] / 2
G0 X#130
G31 Y60. F300.
#103 = #5062
G0 Y30.5
G31 Y0 F300.
#104 = #5062
#131 = [#103 + #104] / 2
#132 = #103 - #104 + 2 * #120
G0 Y#131
G0 Z-200.
G49 G53 G0 Z0
M30
%
