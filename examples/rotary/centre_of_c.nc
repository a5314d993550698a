%
O5201 (CENTRE OF THE C AXIS FROM A BORE AT C0 AND C180)
(The bore of table.scene.toml is found at C0, the table turns to C180 and)
(the bore is found again: the table's axis is half-way between the two.)
(Results, G54: #130 #131 the bore at C0, #140 #141 at C180,)
(#150 #151 the axis of C.)
G21 G90 G17 G40 G54
G43 H20 G0 Z30.
G0 C0
G65 P5291 X72.5 Y2.75
#130 = #198
#131 = #199
G0 C180.
G65 P5291 X-47.5 Y-17.25
#140 = #198
#141 = #199
#150 = [#130 + #140] / 2
#151 = [#131 + #141] / 2
G49 G53 G0 Z0
M30
%
O5291 (BORE CENTRE FROM 4 TOUCHES AT X Y, 10 MM DEEP)
(Returns #198 #199 the centre, in the present work coordinates.)
#10 = #24
#11 = #25
G0 X#10 Y#11
G0 Z-10.
G31 X[#10 + 15.] F300.
#101 = #5061
G0 X#10
G31 X[#10 - 15.] F300.
#102 = #5061
#198 = [#101 + #102] / 2
G0 X#198
G31 Y[#11 + 15.] F300.
#103 = #5062
G0 Y#11
G31 Y[#11 - 15.] F300.
#104 = #5062
#199 = [#103 + #104] / 2
G0 Y#199
G0 Z30.
M99
%
