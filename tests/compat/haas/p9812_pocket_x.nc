%
O1006 (HAAS: POCKET WIDTH IN X - G65 P9812 X.. Q.. S1., NO Z)
( Compatibility: in the style of the probing-x-channel output of )
( Autodesk's "HAAS - Next Generation Control" post [ThomasLeMezo/ )
( enstabretagne-inventor-cam, postpro/haas_vf2_inspect_surface_ENSTA.cps]: )
( a protected move down into the pocket, then G65 P9812 X[width] Q.. S... )
( Constructs: G65 P9812 without Z [touches from inside], S1., the X )
( value written without a trailing zero as posts write it [X50.6]. )
( Expected by hand: G54 = X-15 Y-60 Z-229.87; the pocket [plate.scene. )
( toml] runs from machine X -40.25 to 10.35, its faces at work -25.25 and )
( 25.35: #135 = 0.05, #138 = 50.6, #143 = 0, G54 X = -14.95 [#5221]. )
G00 G17 G40 G49 G80 G90 G94 G97
G21
G10 L2 P1 X-15. Y-60. Z-229.87
T20 M06
#556 = 1.
G65 P9832
G54 G00 X0. Y0.
G43 H20 Z50.
G65 P9810 Z-10. F3000.
G65 P9812 X50.6 Q5. S1.
G65 P9810 Z50. F3000.
G65 P9833
G49 G53 G00 Z0.
M30
%
