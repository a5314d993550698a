%
O02032 (PROBING-Y-PLANE-ANGLE G68)
(Written for skipnc in the output format of the Autodesk Fusion "HAAS -)
(Next Generation Control" post [haas_vf2_inspect_surface_ENSTA.cps of)
(ThomasLeMezo/enstabretagne-inventor-cam: its probing-y-plane-angle case,)
(setProbeAngle with the angle method G68, written at the next operation's)
(start after its work offset, and cancelG68Rotation before the retracts],)
(run unmodified in the haas dialect with -I macros/probing on)
(cycles.machine.toml [G54 X-80 Y30.5 Z-229.5]. The block of)
(angle.scene.toml stands 2 degrees off square, its front face through G54)
(X0 Y-50. Touches at X20 and X60: #136 = -50 + 20 TAN2 - 1 / COS2 + 1 =)
(-49.302194154, #144 = 2. The Haas post reads the results 50 above the)
(Fanuc post's numbers: #186 = #136, #194 = #144 = 2. The next operation,)
(T1, turns its program 2 degrees about G54 X0 Y0 with G68 R[#194]: its)
(X50. Y0. is G54 X50 COS2 = 49.969541351, Y50 SIN2 = 1.744974835,)
(machine X-30.030458649 Y32.244974835 [the report's final position,)
(after G69 and G53 Z0.].)
N10 G90 G94 G17
N15 G21
N20 G53 G0 Z0.
N25 G53 G0 X0. Y0.
N30 T20 M6
N35 G54
N40 G0 X20. Y-60.
N45 G43 Z50. H20
N50 G65 P9832
N55 G65 P9810 Z-5. F1000.
N60 G65 P9843 Y-50. D40. Q5. A0.
N65 G65 P9810 Z50.
N70 G65 P9833
N75 G53 G0 Z0.
N80 T1 M6
N85 G54
N90 G68 G90 X0. Y0. R[#194]
N95 G0 X50. Y0.
N100 G43 Z50. H1
N105 G69
N110 G53 G0 Z0.
N115 M30
%
