%
O5001 (SINGLE SURFACE: THE Z OF THE PLATE'S TOP FACE)
(Scene fixture.scene.toml, machine mill3_probe.machine.toml: the touch)
(probe T20 is in the spindle; H20 is its length to the ball centre, so)
(with G43 H20 a work Z is the ball centre's Z.)
(Result: #100 the top face's Z, work coordinates = machine here.)
#120 = 1.0 (effective ball radius, from calibration)
G21 G90 G17 G40 G54
G43 H20 G0 Z-200.
G0 X30. Y0
G31 Z-240. F200. (towards the top face)
#100 = #5063 - #5083 - #120 (#5063 has H20 in it: less #5083, the ball centre; less its radius, the surface)
G0 Z-200.
G49 G53 G0 Z0
M30
%
