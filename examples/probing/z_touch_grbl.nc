(Z touch-off as a grbl sender's probe macro does it: a fast probe down,)
(back off, a slow probe, then G54 Z set so that the plate's top is Z0.)
(grbl has no tool lengths: work Z is the spindle's gauge line until the)
(offset is set. Run: skipnc run -d grblhal -m mill3_probe.machine.toml)
(  -s fixture.scene.toml z_touch_grbl.nc)
(The probe's ball bottom is 151 mm below the gauge line: H20 150 to the)
(ball centre, ball radius 1. The plate's top is at Z-229.87 in machine)
(coordinates, so the ball touches with the gauge line at Z-78.87.)
(grbl's [PRB:] is where the axis was commanded when the input was seen,)
(a servo period of 1 ms after the touch at most: 5 um at F300, so Z-78.875,)
(0.8 um at F50, so Z-78.871 in its three decimals. G10 L20 then makes the)
(stopped position Z0, and the last move ends at Z5 in G54.)
G21 G90 G17
G53 G0 Z-50.
G53 G0 X30. Y0
G91 G38.2 Z-60. F300. (fast, to find the plate)
G0 Z2. (back off)
G38.2 Z-5. F50. (slow, the touch that counts)
G90 G10 L20 P1 Z0 (the stopped position is Z0 in G54)
G91 G0 Z5.
G90
M2
