%
O5102 (TWO-POINT ANGLE OF A FACE)
(The block's front face touched at X40 and X120, moving +Y, 10 mm below)
(its top: the angle of the line through the two touches, from +X.)
(Results, G54: #141 first Y, #142 second Y, #140 angle in degrees.)
G21 G90 G17 G40 G54
G43 H20 G0 Z30.
G0 X40. Y0
G0 Z-10.
G31 Y30. F300.
#141 = #5062
G0 Y0
G0 X120.
G31 Y30. F300.
#142 = #5062
#140 = ATAN[#142 - #141, 120. - 40.]
G0 Y0
G0 Z30.
G49 G53 G0 Z0
M30
%
