%
O5202 (A SKIP ON THE ROTARY AXIS: THE PART TURNS INTO THE BALL)
(The ball stands still at G54 X40 Y5, 10 mm below the block's top; G31 on)
(C turns the table until the block's face meets it. The ball's centre is)
(1 mm from the face then: 5 COS A - 40 SIN A = 1 for the table's turn A,)
(A = ACOS[1 / SQRT 1625] - ATAN[40, 5] = 5.703537 degrees, C = -A.)
(Result: #160 the C position stored at the touch.)
G21 G90 G17 G40 G54
G43 H20 G0 Z30.
G0 X40. Y5. C0
G0 Z-10.
G31 C-30. F360.
#160 = #5064
G0 Z30.
G49 G53 G0 Z0
M30
%
