%
O0100 (BORE CENTRE: SETS G54 X Y FROM A BORE)
(The bore: 50 mm diameter, centre at machine X100 Y50, measured 10 mm deep.)
(Scene bore.scene.toml: the probe's stylus ball of 5 mm touches the wall)
(when its centre is 22.5 mm from the bore's axis.)
N10 G21 G90 G17 G40 G49 G80 G54
N20 #500=5. (stylus ball diameter, as calibrated)
N30 G53 G0 Z0
N40 G0 X101.2 Y48.7 (near the bore's centre: G54 is still zero)
N50 G65 P8810 Z-10. F2000. (protected move into the bore)
N60 G65 P8814 D50. S1.
N70 G65 P8810 Z0 F3000.
N80 G0 X0 Y0 (the bore's centre in the new G54)
N90 M30
%
