(An arc's end radius against its start radius at the edge of the 0.02 mm tolerance)
(0.0199 and 0.02 mm more are accepted, 0.0201 mm more is PS0020)
G21 G90 G17 F100.
G0 X0 Y0
G2 X20.0199 Y0 I10. J0
G0 X0 Y0
G2 X20.02 Y0 I10. J0
G0 X0 Y0
G2 X20.0201 Y0 I10. J0
M30
