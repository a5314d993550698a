%
O12 (O9801: THE PROBE'S LENGTH CALIBRATED ON THE TOP FACE)
(H20 is set 0.5 short, 150.5 where the gauge line to the ball's lowest)
(point is 151. Touching the top face, G54 Z-0.37, the tip reads 0.5 high:)
(#137 = 0.13, the correction #142 = 0.13 - -0.37 = 0.5, H20 = 151.)
(O9801 applies G43 H20 again: a touch of the same face with O9811 then)
(reads #137 = -0.37, #101 = -0.37; #102 = #5083 = 151.)
N10 G21 G90 G17 G40 G49 G80 G54
N20 #550=1.
N30 G10 L10 P20 R150.5
N40 G53 G0 Z0
N50 G43 H20 G0 X20. Y-20.
N60 G65 P9810 Z5. F3000.
N70 G65 P9801 Z-0.37 T20 Q5.
N80 #103=#142
N90 G65 P9811 Z-0.37 Q5.
N100 #101=#137
N110 #102=#5083
N120 G65 P9810 Z50.
N130 M30
%
