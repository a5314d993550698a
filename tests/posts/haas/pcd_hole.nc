%
O02023 (PROBING-XY-PCD-HOLE)
(Written for skipnc in the output format of the Autodesk Fusion "HAAS -)
(Next Generation Control" post [its probing case for this operation;)
(haas_vf2_inspect_surface_ENSTA.cps of ThomasLeMezo/enstabretagne-)
(inventor-cam], the Fanuc-post program ../pcd_hole.nc in the Haas framing,)
(run unmodified in the haas dialect with -I macros/probing;)
(probe.vars is the control memory: #550 = 1.)
(The scene of golden probing_cycles/o9819_pitch_circle: four holes 10.)
(across on a 60. circle, its centre at G54 X100.05 Y-60.47, the first)
(hole at 47 degrees. CAD: centre X100. Y-60.5, first at 45; holes)
(measured at K-5. The post writes no S for this cycle: #135 = 100.05,)
(#136 = -60.47, #138 = 10, #139 = 47, #144 = 47 - 45 = 2, #147 = 4;)
(G54 X stays -80.)
N10 G90 G94 G17
N15 G21
N20 G53 G0 Z0.
N25 G53 G0 X0. Y0.
N30 T20 M6
N35 G54
N40 G0 X100. Y-60.5
N45 G43 Z50. H20
N50 G65 P9832
N55 G65 P9810 Z0. F1000.
N60 G65 P9819 A45. B4. C60. D10. K-5. Q5.
N65 G65 P9810 Z50.
N70 G65 P9833
N75 G53 G0 Z0.
N80 G53 G0 X0. Y0.
N85 M30
%
