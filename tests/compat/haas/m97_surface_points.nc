%
O1007 (HAAS: THREE Z POINTS BY A LOCAL SUBPROGRAM - M97 P1000 L3)
( Compatibility: in the style of the local subprograms Autodesk's "HAAS - )
( Next Generation Control" post writes for patterns [ThomasLeMezo/ )
( enstabretagne-inventor-cam, postpro/haas_vf2_inspect_surface_ENSTA.cps, )
( subprogramCall and subprogramEnd: M97 P<n> in the program, N<n> ... M99 )
( after M30], with the repeat count of Haas's own M97 example [Haas mill )
( operator's manual 96-8000, "M97 Local Sub-Program Call": M97 P1000 L5]. )
( Constructs: M97 P.. L.., N1000 after M30, G91 inside the sub then G90, )
( G65 P9811 Z.. from a local subprogram, M99 back to the block after M97, )
( common variables summed across the repetitions. )
( Expected by hand: G54 = X20 Y0 Z-225; each pass steps 10 in X [machine )
( 30, 40, 50, all over the plate] and touches the top at -229.87 = work )
( -4.87: #101 = 3 passes, #100 = 3 x -4.87 = -14.61, #102 = #5041 = 30, )
( the last point's work X. )
G00 G17 G40 G49 G80 G90 G94 G97
G21
G10 L2 P1 X20. Y0. Z-225.
T20 M06
#556 = 1.
#100 = 0
#101 = 0
G65 P9832
G54 G00 X0. Y0.
G43 H20 Z50.
G65 P9810 Z5. F3000.
M97 P1000 L3
#102 = #5041
G65 P9810 Z50. F3000.
G65 P9833
G49 G53 G00 Z0.
M30
N1000 (ONE POINT: A STEP IN X, A Z TOUCH)
G91 G00 X10.
G90
G65 P9811 Z-5. Q5.
#100 = #100 + #137
#101 = #101 + 1
M99
%
