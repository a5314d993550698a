%
O1003 (HAAS: BORE CENTRE AND DIAMETER, G54 X Y SET - G65 P9814 D.. Q.. S1.)
( Compatibility: in the style of the probing-xy-circular-hole output of )
( Autodesk's "HAAS - Next Generation Control" post [ThomasLeMezo/ )
( enstabretagne-inventor-cam, postpro/haas_vf2_inspect_surface_ENSTA.cps]: )
( a protected move down into the bore, then G65 P9814 D[diameter] )
( Q[overtravel] S1. without Z [a bore]. )
( Constructs: G65 P9814 with D, Q, S; our O9814 calling our O9819 twice )
( [two macro levels], four G31 with F in the block, the X centre found )
( before the Y touches, #5221 #5222 corrected. )
( Expected by hand: G54 = X-80 Y30 Z-225 puts the nominal centre at work )
( 0,0; the bore [plate.scene.toml] is 40 mm at machine -80.123, 30.456. )
( The X touches are symmetric about the true X centre whatever the chord: )
( #135 = -80.123 + 80 = -0.123. The Y touches go through that centre and )
( meet the wall at 30.456 +- 20: #136 = 0.456, #138 = 40, #143 = 0. S1. )
( adds the errors to G54: #5221 = -80.123, #5222 = 30.456. )
G00 G17 G40 G49 G80 G90 G94 G97
G21
G10 L2 P1 X-80. Y30. Z-225.
T20 M06
#556 = 1.
G65 P9832
G54 G00 X0. Y0.
G43 H20 Z50.
G65 P9810 Z-15. F3000.
G65 P9814 D40. Q5. S1.
G65 P9810 Z50. F3000.
G65 P9833
G49 G53 G00 Z0.
M30
%
