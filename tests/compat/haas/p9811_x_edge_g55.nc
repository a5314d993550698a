%
O1002 (HAAS: X EDGE, G55 X CORRECTED - G65 P9811 X.. Q.. S2.)
( Compatibility: in the style of the probing-x output of Autodesk's )
( "HAAS - Next Generation Control" post [ThomasLeMezo/enstabretagne- )
( inventor-cam, postpro/haas_vf2_inspect_surface_ENSTA.cps, onCyclePoint )
( "probing-x"]: a protected move down beside the part, then G65 P9811 )
( X[edge + clearance + ball] Q[overtravel] S2. for G55. )
( Constructs: safe-start G17 G40 G49 G80 G90 G94 G97 written as the post )
( splits it, G55 selected and written by G10 L2 P2, G65 P9810 with Z only, )
( G65 P9811 X.., #5041 [X has no tool length], #5241 corrected. )
( Expected by hand: G55 X = 100, so the nominal edge X49. is machine 149; )
( the plate's +X face is at machine 150. Coming from work X60 [machine )
( 160] toward -X, the ball touches with its centre at machine 151 = work )
( 51; the face is one radius further: #135 = 50, #140 = 50 - 49 = 1, and )
( S2. makes G55 X = 100 + 1 = 101 [#5241]. )
G17 G40 G49 G80 G90
G94 G97
G21
G10 L2 P2 X100. Y0. Z-225.
T20 M06
#556 = 1.
G65 P9832
G55 G00 X60. Y0.
G43 H20 Z50.
G65 P9810 Z-10. F3000.
G65 P9811 X49. Q5. S2.
G65 P9810 Z50. F3000.
G65 P9833
G49 G53 G00 Z0.
M30
%
