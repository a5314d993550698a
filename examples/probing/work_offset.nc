%
O5008 (WORK OFFSET FROM THE BORE CENTRE AND THE TOP FACE)
(G54 X Y is set to the bore's centre, G54 Z to the plate's top face, with)
(G10 L2 P1; the probe then goes to X0 Y0 Z5 of G54.)
(Results: #5221 #5222 #5223, G54 X Y Z.)
#120 = 1.0 (effective ball radius, from calibration)
G21 G90 G17 G40 G54
G43 H20 G0 Z-200.
G0 X30. Y0
G31 Z-240. F200.
#100 = #5063 - #5083 - #120 (the top face: #5063 has the H20 length in it)
G0 Z-200.
G0 X-80. Y30.5
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
G0 Y#131
G0 Z-200.
(G54 was zero: the values found are machine coordinates)
G10 L2 P1 X#130 Y#131 Z#100
G0 X0 Y0 Z30.
G0 Z5.
G49 G53 G0 Z0
M30
%
