(LinuxCNC's arc check at the edge of its tolerance, 2 * 0.01 mm * sqrt 2)
(0.028 mm more is accepted, 0.0284 mm, more than the tolerance and 0.1 % of the radius, is refused)
G21 G90 G17 F100.
G0 X0 Y0
G2 X20.028 Y0 I10. J0
G0 X0 Y0
G2 X20.0284 Y0 I10. J0
M2
