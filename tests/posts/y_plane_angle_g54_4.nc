%
O2031 (PROBING-Y-PLANE-ANGLE G54.4)
(Written for skipnc in the output format of the Autodesk Fusion generic)
(Fanuc post [fanuc.cps: its probing-y-plane-angle case, setProbeAngle with)
(the angle method G54.4 [property useG54x4], onClose's G54.4 P0], run)
(unmodified with -I macros/probing on cycles.machine.toml [G54 X-80 Y30.5)
(Z-229.5]. The block of angle.scene.toml stands 2 degrees off square,)
(its front face through G54 X0 Y-50. Touches at X20 and X60: #135 vacant)
(a Y face], #136 = -50 + 20 TAN2 - 1 / COS2 + 1 = -49.302194154, #144 = 2.)
(The post writes them as set 1's dx dy dc and selects G54.4 P1: work =)
([0, #136] + R[2 deg] p. The next operation's X50. Y0. is then G54 X50 COS2)
(= 49.969541351, Y #136 + 50 SIN2 = -47.557219319: machine X-30.030458649)
(Y-17.057219319 [the report's final position, after G53 Z0.]. The post)
(writes the surface's position at the first touch [X20], not its error,)
(as dy, and G54.4 turns about G54 X0: the program's Y0 runs parallel to)
(the face through G54 X0 Y#136, 20 SIN2 - 1 + COS2 = 0.697 mm off it.)
N10 G90 G94 G17 G49 G40 G80
N15 G21
N20 G53 G0 Z0.
N25 T20 M6
N30 G54 G0 X20. Y-60.
N35 G43 Z50. H20
N40 G65 P9832
N45 G65 P9810 Z-5. F1000.
N50 G65 P9843 Y-50. D40. Q5. A0.
N55 G65 P9810 Z50.
N60 G65 P9833
N65 #26010=#135
N70 #26011=#136
N75 #26015=#144
N80 G54.4 P1
N85 G54 G0 X50. Y0.
N90 G43 Z50. H20
N95 G53 G0 Z0.
N100 G54.4 P0
N105 M30
%
