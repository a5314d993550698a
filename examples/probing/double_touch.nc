%
O5007 (FAST THEN SLOW TOUCH)
(A fast touch finds the surface, the probe backs off 2 mm and a slow)
(touch measures it. With the exact latch both agree; with a sampled latch)
(double_touch_sampled.machine.toml, the fast one is off by up to a servo)
(period of travel.)
(Results: #100 the surface, from the slow touch; #103 fast minus slow.)
#120 = 1.0 (effective ball radius, from calibration)
G21 G90 G17 G40 G54
G43 H20 G0 Z-200.
G0 X30. Y0
G31 Z-240. F1000. (fast)
#101 = #5063 - #5083 (#5063 has the H20 length in it)
G91 G0 Z2.
G90 G31 Z-240. F50. (slow)
#102 = #5063 - #5083
G0 Z-200.
#100 = #102 - #120
#103 = #101 - #102
G49 G53 G0 Z0
M30
%
