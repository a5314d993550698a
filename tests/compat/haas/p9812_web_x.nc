%
O1005 (HAAS: WEB WIDTH AND CENTRE IN X - G65 P9812 X.. Z.. Q.. R.. S1.)
( Compatibility: in the style of the probing-x-wall output of Autodesk's )
( "HAAS - Next Generation Control" post [ThomasLeMezo/enstabretagne- )
( inventor-cam, postpro/haas_vf2_inspect_surface_ENSTA.cps, onCyclePoint )
( "probing-x-wall": G65 P9812 X[width] Z[z - depth] Q.. R.. S..]. )
( Constructs: G65 P9812 with a width X, Z [a web], Q, R and S1.; our )
( O9812 calling O9819 [out by R, down to Z, touch inward, back up]. )
( Expected by hand: G54 = X106.5 Y50 Z-209.87 [work Z0 on the web's top]; )
( the web [plate.scene.toml] runs from machine X 100.2 to 112.7: its )
( faces are at work 6.2 and -6.3, so #135 = -0.05 [the centre], #138 = )
( 12.5, #143 = 0, #140 = -0.05, and S1. moves G54 X to 106.45 [#5221]. )
G00 G17 G40 G49 G80 G90 G94 G97
G21
G10 L2 P1 X106.5 Y50. Z-209.87
T20 M06
#556 = 1.
G65 P9832
G54 G00 X0. Y0.
G43 H20 Z50.
G65 P9810 Z10. F3000.
G65 P9812 X12.5 Z-5. Q5. R5. S1.
G65 P9810 Z50. F3000.
G65 P9833
G49 G53 G00 Z0.
M30
%
