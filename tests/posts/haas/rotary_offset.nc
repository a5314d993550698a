%
O02033 (PROBING-Y-PLANE-ANGLE ROTARY)
(Written for skipnc in the output format of the Autodesk Fusion "HAAS -)
(Next Generation Control" post [haas_vf2_inspect_surface_ENSTA.cps of)
(ThomasLeMezo/enstabretagne-inventor-cam: its probing-y-plane-angle case,)
(setProbeAngle with the angle method AXIS_ROT, chosen for a table axis)
(about Z, written after the cycle's G65 P9833; the rotary axes unclamped)
(M11 M13 and clamped M10 M12 around each G0 A C], run unmodified in the)
(haas dialect with -I macros/probing on ../rotary.machine.toml, X Y Z A C.)
(The post updates the rotary work offset by the axis's letter:)
(#[5200 + 20 n + k + 4] = [that + #194], k = 2 for C: #5226 for G54,)
(G54's C as Haas numbers the offsets [X Y Z A B C, whatever the axes].)
(The block of rotary.scene.toml stands 2 degrees off square at C0. First)
(cycle, touches at X20 and X60: #136 = -50 + 20 TAN2 - 1 / COS2 + 1 =)
(-49.302194154, #144 = 2; the Haas post reads the copy #194 = 2.)
(#5226 = 0 + 2. The next operation writes G54 again and C0.: the machine)
(C is 2, the table turns 2 degrees clockwise about G54 X0 Y0, the face is)
(square, through Y-50 COS2: the second cycle reads #186 = #136 =)
(-50 COS2 = -49.969541351, #194 = 0, and #5226 stays 2.)
N10 G90 G94 G17
N15 G21
N20 G53 G0 Z0.
N25 G53 G0 X0. Y0.
N30 T20 M6
N35 G54
N40 M11
N45 M13
N50 G0 A0. C0.
N55 M10
N60 M12
N65 G0 X20. Y-60.
N70 G43 Z50. H20
N75 G65 P9832
N80 G65 P9810 Z-5. F1000.
N85 G65 P9843 Y-50. D40. Q5. A0.
N90 G65 P9810 Z50.
N95 G65 P9833
N100 #5226 = [#5226 + #194]
N105 G54
N110 M11
N115 M13
N120 G53 G0 Z0.
N125 G53 G0 X0. Y0.
N130 G0 A0. C0.
N135 M10
N140 M12
N145 G0 X20. Y-60.
N150 G43 Z50. H20
N155 G65 P9832
N160 G65 P9810 Z-5. F1000.
N165 G65 P9843 Y-50. D40. Q5. A0.
N170 G65 P9810 Z50.
N175 G65 P9833
N180 #5226 = [#5226 + #194]
N185 G53 G0 Z0.
N190 G53 G0 X0. Y0.
N195 M30
%
