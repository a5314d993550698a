(Collision: the ball goes down 2 mm beside the clamp, but the probe's)
(body, 20 mm above the ball and 40 mm across, lands on the clamp's top at)
(Z-190: alarm 9062 with the ball centre at Z-210, machine Z-60.)
G21 G90 G54
G43 H20 G0 Z-150.
G0 X-13. Y75.
G1 Z-220. F1000.
G0 Z-150.
M30
