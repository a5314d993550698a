%
O5101 (BORE CENTRE IN G54)
(The bore of plate_g54.scene.toml, or of plate_machine.scene.toml: the same)
(part, placed in G54 or in machine coordinates; the results are the same.)
(Results, G54: #130 X centre, #131 Y centre, #132 diameter.)
#120 = 1.0 (effective ball radius)
G21 G90 G17 G40 G54
G43 H20 G0 Z30.
G0 X70. Y130.5 (the drawing's position)
G0 Z-10.
G31 X100. F300.
#101 = #5061
G0 X70.
G31 X40. F300.
#102 = #5061
#130 = [#101 + #102] / 2
G0 X#130
G31 Y160. F300.
#103 = #5062
G0 Y130.5
G31 Y100. F300.
#104 = #5062
#131 = [#103 + #104] / 2
#132 = #103 - #104 + 2 * #120
G0 Y#131
G0 Z30.
G49 G53 G0 Z0
M30
%
