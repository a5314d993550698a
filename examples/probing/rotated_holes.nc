%
O5010 (ROTATED HOLES: PROBE TWO BORES, G68, DRILL WITH G81)
(The plate lies turned on the table. Probe bore A, the datum, and bore B,)
(whose direction from A is the plate's X axis. G68 turns the program by the)
(measured angle about A; the holes are then programmed as on the drawing:)
(25, 50 and 75 mm from A along X, and drilled with G81.)
(Results: #120 #121 centre of A, #122 #123 centre of B, #140 the angle,)
(#151-#156 the drilled holes' work positions X, Y.)
G21 G90 G17 G40 G54
G43 H20 G0 Z-200.
(Bore A at its drawing position, then bore B 100 mm away at 12 degrees)
#110 = -60.
#111 = -20.
M98 P5011
#120 = #130
#121 = #131
#110 = 37.8
#111 = 0.8
M98 P5011
#122 = #130
#123 = #131
G0 Z-200.
#140 = ATAN[#123 - #121] / [#122 - #120]
(Drill: the drill in the spindle, the program turned about A)
G49 G53 G0 Z0
T1 M06
G43 H1 G0 Z-200.
M03 S1500
G68 X#120 Y#121 R#140
G99 G81 X[#120 + 25.] Y#121 Z-240. R-227. F200.
#151 = #5041
#152 = #5042
X[#120 + 50.]
#153 = #5041
#154 = #5042
X[#120 + 75.]
#155 = #5041
#156 = #5042
G80 G69
G0 Z-200.
M05
G49 G53 G0 Z0
M30

O5011 (BORE CENTRE AT #110 #111: X+ X- AT THE DRAWING Y, Y+ Y- AT THE X CENTRE)
G0 X#110 Y#111
G0 Z-239.87
G31 X[#110 + 15.] F300.
#101 = #5061
G0 X#110
G31 X[#110 - 15.] F300.
#102 = #5061
#130 = [#101 + #102] / 2
G0 X#130
G31 Y[#111 + 15.] F300.
#103 = #5062
G0 Y#111
G31 Y[#111 - 15.] F300.
#104 = #5062
#131 = [#103 + #104] / 2
G0 Y#131
G0 Z-200.
M99
%
