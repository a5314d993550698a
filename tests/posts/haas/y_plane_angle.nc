%
O02022 (PROBING-Y-PLANE-ANGLE)
(Written for skipnc in the output format of the Autodesk Fusion "HAAS -)
(Next Generation Control" post [its probing case for this operation;)
(haas_vf2_inspect_surface_ENSTA.cps of ThomasLeMezo/enstabretagne-)
(inventor-cam], the Fanuc-post program ../y_plane_angle.nc in the Haas framing,)
(run unmodified in the haas dialect with -I macros/probing; probe.vars is the control memory:)
(#550 = 1 [the ball calibrated]. The part [part.scene.toml] sits off)
(its CAD place by X-0.123 Y-0.044 Z-0.37 in G54 X-80 Y30.5 Z-229.5,)
(the CAD features below are the true ones + [0.123, 0.044, 0.37]:)
(the plate -Y face, along X: touches 20. apart along X, A0.: #136 =)
(-130.5, #141 = -0.044, #139 = 0, #144 = 0; G54 Y stays 30.5.)
N10 G90 G94 G17
N15 G21
N20 G53 G0 Z0.
N25 G53 G0 X0. Y0.
N30 T20 M6
N35 G54
N40 G0 X0. Y-136.456
N45 G43 Z50. H20
N50 G65 P9832
N55 G65 P9810 Z-5. F1000.
N60 G65 P9843 Y-130.456 D20. Q5. A0.
N65 G65 P9810 Z50.
N70 G65 P9833
N75 G53 G0 Z0.
N80 G53 G0 X0. Y0.
N85 M30
%
