%
O2032 (PROBING-XY-OUTER-CORNER WITH PROBE SPACING, G68)
(Written for skipnc in the output format of the Autodesk Fusion generic)
(Fanuc post [fanuc.cps: its probing-xy-outer-corner case with a probe)
(spacing, which writes I and J and sets the angle method; setProbeAngle's)
(G68 case, G68 G90 X[#135] Y[#136] Z0. I0. J0. K1. R[#144], at the next)
(operation's start], run unmodified with -I macros/probing on)
(cycles.machine.toml [G54 X-80 Y30.5 Z-229.5]. The block of)
(angle.scene.toml stands 2 degrees off square about its front-left)
(corner, G54 X0 Y-50; the faces are touched twice, 10. apart: the corner)
(is exact, #135 = 0, #136 = -50, the left face's angle error #144 = 2;)
(S1. moves G54 by the corner's error, 0. The next operation, T1, turns)
(its program 2 degrees about K through the corner: its X50. Y0. is G54)
(50 COS2 - 50 SIN2 = 48.224566516, -50 + 50 SIN2 + 50 COS2 =)
(1.714516186, machine X-31.775433484 Y32.214516186 [the report's final)
(position, after G69 and G53 Z0.].)
N10 G90 G94 G17 G49 G40 G80
N15 G21
N20 G53 G0 Z0.
N25 T20 M6
N30 G54 G0 X-6. Y-56.
N35 G43 Z50. H20
N40 G65 P9832
N45 G65 P9810 Z-5. F1000.
N50 G65 P9816 X0. Y-50. I10. J10. Q5. S1.
N55 G65 P9810 Z50.
N60 G65 P9833
N65 G53 G0 Z0.
N70 T1 M6
N75 G54
N80 G68 G90 X[#135] Y[#136] Z0. I0. J0. K1. R[#144]
N85 G0 X50. Y0.
N90 G43 Z50. H1
N95 G69
N100 G53 G0 Z0.
N105 M30
%
