%
O02011 (PROBING-XY-CIRCULAR-PARTIAL-BOSS)
(Written for skipnc in the output format of the Autodesk Fusion "HAAS -)
(Next Generation Control" post [its probing case for this operation;)
(haas_vf2_inspect_surface_ENSTA.cps of ThomasLeMezo/enstabretagne-)
(inventor-cam], the Fanuc-post program ../partial_boss.nc in the Haas framing,)
(run unmodified in the haas dialect with -I macros/probing; probe.vars is the control memory:)
(#550 = 1 [the ball calibrated]. The part [part.scene.toml] sits off)
(its CAD place by X-0.123 Y-0.044 Z-0.37 in G54 X-80 Y30.5 Z-229.5,)
(the CAD features below are the true ones + [0.123, 0.044, 0.37]:)
(the boss from three points at 0, 120, 240 degrees: as the full boss,)
(#135 = 140.789, #136 = -70.821, #138 = 30; S1.)
N10 G90 G94 G17
N15 G21
N20 G53 G0 Z0.
N25 G53 G0 X0. Y0.
N30 T20 M6
N35 G54
N40 G0 X140.912 Y-70.777
N45 G43 Z50. H20
N50 G65 P9832
N55 G65 P9810 Z25. F1000.
N60 G65 P9823 A0. B120. C240. D30. Z15. Q5. R5. S1.
N65 G65 P9810 Z50.
N70 G65 P9833
N75 G53 G0 Z0.
N80 G53 G0 X0. Y0.
N85 M30
%
