%
O5103 (TILT OF A TOP FACE ALONG X AND ALONG Y)
(The top of the block in sine_plate.scene.toml touched from above at four)
(points: the slope of the line through two touches is the face's angle)
(along that axis, whatever the ball's radius.)
(Results, G54: #150 angle along X, #151 angle along Y, in degrees.)
G21 G90 G17 G40 G54
G43 H20 G0 Z30.
G0 X30. Y30.
G0 Z5.
G31 Z-10. F200.
#141 = #5063
G0 Z5.
G0 X110.
G31 Z-10. F200.
#142 = #5063
G0 Z5.
G0 X30. Y25.
G31 Z-10. F200.
#143 = #5063
G0 Z5.
G0 Y75.
G31 Z-10. F200.
#144 = #5063
G0 Z30.
#150 = ATAN[#142 - #141, 110. - 30.]
#151 = ATAN[#144 - #143, 75. - 25.]
G49 G53 G0 Z0
M30
%
