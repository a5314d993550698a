%
O1001 (HAAS: Z SURFACE, G54 Z CORRECTED - G65 P9811 Z.. Q.. S1.)
( Compatibility: in the style of the probing-z output of Autodesk's )
( "HAAS - Next Generation Control" post, as kept in the repository )
( ThomasLeMezo/enstabretagne-inventor-cam, postpro/haas_vf2_inspect_ )
( surface_ENSTA.cps [onCyclePoint "probing-z", protectedProbeMove]: )
( G65 P9832 probe on, G65 P9810 Z.. F.. protected moves, G65 P9811 Z.. )
( Q.. S1. with the work offset written "S1.", G65 P9833 probe off. )
( Constructs: the post's safe-start line G00 G17 G40 G49 G80 G90 G94 )
( G97, G21, G10 L2 P1, T20 M06, G43 H20, G65 arguments with decimal )
( points, our own O9810/O9811/O9832/O9833 [macros/], #3000 alarms kept )
( for a miss, #5043 #5063 #5083 [the tool length inside them], #5223 )
( written by the macro. )
( Expected by hand: G54 Z = -225, so the nominal surface Z-5 is machine )
( -230; the plate's top is at -229.87 [plate.scene.toml]. With H20 = 150 )
( to the ball centre the ball touches with its centre at machine )
( -228.87 = work -3.87; the surface is one ball radius [#556 = 1] lower: )
( #137 = -4.87, #142 = -4.87 - [-5] = 0.13, and S1. adds the error to )
( G54 Z: #5223 = -225 + 0.13 = -224.87. #150 = 0: the probe is off. )
G00 G17 G40 G49 G80 G90 G94 G97
G21
G10 L2 P1 X30. Y0. Z-225.
T20 M06
#556 = 1. (the ball's calibrated radius)
G65 P9832
G54 G00 X0. Y0.
G43 H20 Z50.
G65 P9810 Z5. F3000.
G65 P9811 Z-5. Q5. S1.
G65 P9810 Z50. F3000.
G65 P9833
G49 G53 G00 Z0.
M30
%
