%
O2030 (PROBING-Y-PLANE-ANGLE ROTARY)
(Written for skipnc in the output format of the Autodesk Fusion generic)
(Fanuc post [fanuc.cps: its probing-y-plane-angle case, and setProbeAngle)
(with the angle method AXIS_ROT, chosen for a table axis about Z], run)
(unmodified with -I macros/probing on rotary.machine.toml, X Y Z A C. The)
(post updates the rotary work offset after the angle cycle:)
(#[5200 + 20 n + 5] = [that + #144], for G54 #5225, here G54's C.)
(The block [rotary.scene.toml] stands 2 degrees off square at C0. First)
(cycle, touches at X20 and X60: the face at X20 is at Y-50 + 20 TAN2, the)
(ball's centre 1 / COS2 in front of it, the surface read +1: #136 =)
(-50 + 20 TAN2 - 1 / COS2 + 1 = -49.302194154, #144 = 2 - 0 = 2.)
(#5225 = 0 + 2. The next operation re-selects G54 and C0.: the machine C)
(is 2, the table turns 2 degrees clockwise [a table axis] about G54 X0 Y0,)
(the face is square, through Y-50 COS2: the second cycle reads #136 =)
(-50 COS2 = -49.969541351, #144 = 0, and #5225 stays 2.)
N10 G90 G94 G17 G49 G40 G80
N15 G21
N20 G53 G0 Z0.
N25 T20 M6
N30 G0 A0. C0.
N35 G54 G0 X20. Y-60.
N40 G43 Z50. H20
N45 G65 P9832
N50 G65 P9810 Z-5. F1000.
N55 G65 P9843 Y-50. D40. Q5. A0.
N60 G65 P9810 Z50.
N65 G65 P9833
N70 #5225 = [#5225 + #144]
N75 G0 A0. C0.
N80 G54 G0 X20. Y-60.
N85 G43 Z50. H20
N90 G65 P9832
N95 G65 P9810 Z-5. F1000.
N100 G65 P9843 Y-50. D40. Q5. A0.
N105 G65 P9810 Z50.
N110 G65 P9833
N115 #5225 = [#5225 + #144]
N120 G53 G0 Z0.
N125 M30
%
