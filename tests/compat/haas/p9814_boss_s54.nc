%
O1004 (HAAS: BOSS CENTRE AND DIAMETER - G65 P9814 D30. Z-5. S54.)
( Compatibility: in the style of the Renishaw Inspection Plus call as Haas )
( shops write it, G65 P9814 D50. Z-5. S54. [work offset named by its G )
( number], and of the probing-xy-circular-boss output of Autodesk's "HAAS )
( - Next Generation Control" post [ThomasLeMezo/enstabretagne-inventor- )
( cam, postpro/haas_vf2_inspect_surface_ENSTA.cps]: D, Z, Q, R. )
( Constructs: G65 P9814 with Z [a boss], R radial clearance, S54. for G54; )
( our O9814/O9819 going out by R, down to Z, touching inward, back up. )
( Expected by hand: G54 = X60 Y-40 Z-209.87 [work Z0 on the boss's top]; )
( the boss [plate.scene.toml] is 30 mm at machine 60.789, -40.321. The X )
( touches are symmetric about its centre: #135 = 0.789; the Y touches go )
( through it and meet the side at -40.321 +- 15: #136 = -0.321, #138 = 30. )
( S54. corrects G54: #5221 = 60.789, #5222 = -40.321. )
G00 G17 G40 G49 G80 G90 G94 G97
G21
G10 L2 P1 X60. Y-40. Z-209.87
T20 M06
#556 = 1.
G65 P9832
G54 G00 X0. Y0.
G43 H20 Z50.
G65 P9810 Z10. F3000.
G65 P9814 D30. Z-5. Q5. R5. S54.
G65 P9810 Z50. F3000.
G65 P9833
G49 G53 G00 Z0.
M30
%
