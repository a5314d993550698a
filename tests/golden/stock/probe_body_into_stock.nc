(The probe beside the stock: its ball goes down clear of it, 9 mm off its)
(left face, but the probe's body, 40 mm across and 50 mm above the ball,)
(lands on its top: alarm 9062 with the ball at G54 Z-50, the gauge line)
(at machine Z-100, line 7.)
G21 G90 G54
G43 H20 G0 Z20. X-10. Y20.
G1 Z-60. F1000.
M30
