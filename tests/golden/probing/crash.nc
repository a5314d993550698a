(Probe crash: G31 at F3000 onto the plate's top face. The axes need)
(50/30 mm of following error on mill3_lowgain plus a servo period to stop, more than the)
(stylus's 0.5 mm of over-travel: a warning before the move, then alarm)
(9061 where the deflection passes 0.5 mm, ball centre at Z-229.37.)
G21 G90 G54
G43 H20 G0 Z-200.
G0 X30. Y0
G31 Z-240. F3000.
G0 Z-200.
M30
