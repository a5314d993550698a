%
O2023 (PROBING-XY-PCD-HOLE)
(Written for skipnc in the output format of the Autodesk Fusion generic)
(Fanuc post, fanuc.cps, run unmodified with -I macros/probing;)
(probe.vars is the control memory: #550 = 1.)
(The scene of golden probing_cycles/o9819_pitch_circle: four holes 10.)
(across on a 60. circle, its centre at G54 X100.05 Y-60.47, the first)
(hole at 47 degrees. CAD: centre X100. Y-60.5, first at 45; holes)
(measured at K-5. The post writes no S for this cycle: #135 = 100.05,)
(#136 = -60.47, #138 = 10, #139 = 47, #144 = 47 - 45 = 2, #147 = 4;)
(G54 X stays -80.)
N10 G90 G94 G17 G49 G40 G80
N15 G21
N20 G53 G0 Z0.
N25 T20 M6
N30 G54 G0 X100. Y-60.5
N35 G43 Z50. H20
N40 G65 P9832
N45 G65 P9810 Z0. F1000.
N50 G65 P9819 A45. B4. C60. D10. K-5. Q5.
N55 G65 P9810 Z50.
N60 G65 P9833
N65 G53 G0 Z0.
N70 M30
%
