(Probe protection: a G01 move, not a skip move, runs the ball into the)
(clamp's side at X-10: alarm 9063 where the probe switches, ball centre)
(at X-11.)
G21 G90 G54
G43 H20 G0 Z-150.
G0 X-30. Y75.
G0 Z-215.
G1 X30. F500.
G0 Z-150.
M30
