%
O02024 (PROBING-XY-PCD-BOSS)
(Written for skipnc in the output format of the Autodesk Fusion "HAAS -)
(Next Generation Control" post [its probing case for this operation;)
(haas_vf2_inspect_surface_ENSTA.cps of ThomasLeMezo/enstabretagne-)
(inventor-cam], the Fanuc-post program ../pcd_boss.nc in the Haas framing,)
(run unmodified in the haas dialect with -I macros/probing;)
(probe.vars is the control memory: #550 = 1.)
(pcd.scene.toml: three bosses 10. across, 10. tall on a 60. circle;)
(CAD centre X20. Y-60., first at 30 degrees, top Z10.; true centre)
(G54 X20 - 0.123 = 19.877, Y-60 - 0.044 = -60.044, top 9.63. From Z15.)
(each boss touched at Z5. from R5. outside: #135 = 19.877, #136 =)
(-60.044, #138 = 10, #139 = 30, #140 = -0.123, #141 = -0.044, #142 = 0,)
(#147 = 3; no S: G54 X stays -80.)
N10 G90 G94 G17
N15 G21
N20 G53 G0 Z0.
N25 G53 G0 X0. Y0.
N30 T20 M6
N35 G54
N40 G0 X20. Y-60.
N45 G43 Z50. H20
N50 G65 P9832
N55 G65 P9810 Z15. F1000.
N60 G65 P9819 A30. B3. C60. D10. Z5. Q5. R5.
N65 G65 P9810 Z50.
N70 G65 P9833
N75 G53 G0 Z0.
N80 G53 G0 X0. Y0.
N85 M30
%
