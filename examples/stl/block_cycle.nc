%
O5021 (STL BLOCK: TOP FACE, BORE, BOSS, CHAMFER)
(Scene block.scene.toml, machine ../frames/cell.machine.toml: the block of)
(block.stl and the boss of boss.stl, placed with their corner at G54 X20)
(Y20; the probe T20 in the spindle, H20 its length to the ball centre, so)
(with G43 H20 a work Z is the ball centre's Z.)
(The bore and the boss are 128-sided polygons with their corners on the)
(circle. A ball going out from the bore's centre meets two sides either)
(side of a corner and stops 1 / cos[180 / 128] = 1.000301 mm short of it:)
(the bore reads 23.999398 across, not 24. Coming at the boss, it meets)
(the corner itself: the boss reads exactly.)
(Results: #100 top face Z; #130, #131 bore centre; #132 bore diameter;)
(#140, #141 boss centre; #150 the chamfer's Z 1 mm in from the edge.)
#120 = 1.0 (effective ball radius, from calibration)
G21 G90 G17 G40 G54
G43 H20 G0 Z30.
(The top face, between the bore and the edge.)
G0 X30. Y60.
G31 Z-10. F300.
#100 = #5063 - #5083 - #120 (#5063 has H20 in it)
G0 Z30.
(The bore: four touches 10 mm below the top face.)
G0 X60. Y60.
G0 Z-10.
G31 X80. F300.
#101 = #5061
G0 X60.
G31 X40. F300.
#102 = #5061
#130 = [#101 + #102] / 2
G0 X#130
G31 Y80. F300.
#103 = #5062
G0 Y60.
G31 Y40. F300.
#104 = #5062
#131 = [#103 + #104] / 2
#132 = #103 - #104 + 2 * #120
G0 Y#131
G0 Z30.
(The boss, 16 mm across at G54 X84 Y84: four touches from outside at Z5.)
G0 X70. Y84.
G0 Z5.
G31 X84. F300.
#105 = #5061
G0 X70.
G0 Z15.
G0 X98.
G0 Z5.
G31 X84. F300.
#106 = #5061
G0 X98.
G0 Z15.
#140 = [#105 + #106] / 2
G0 X#140 Y70.
G0 Z5.
G31 Y84. F300.
#107 = #5062
G0 Y70.
G0 Z15.
G0 Y98.
G0 Z5.
G31 Y84. F300.
#108 = #5062
G0 Y98.
G0 Z30.
#141 = [#107 + #108] / 2
(The chamfer, 2 mm at 45 degrees: a Z touch 1 mm in from the block's edge)
(stops with the ball centre sqrt[2] over the face's point under it.)
G0 X99. Y30.
G31 Z-10. F300.
#150 = #5063 - #5083 - 1.41421356 * #120
G0 Z30.
G49 G53 G0 Z0
M30
%
