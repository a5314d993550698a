%
O1008 (HAAS: SURFACE INSPECTION POINT, G31 THEN G103 P1 - POINT TAKEN)
( Compatibility: in the style of the surface inspection Autodesk's "HAAS - )
( Next Generation Control" post writes [ThomasLeMezo/enstabretagne- )
( inventor-cam, postpro/haas_vf2_inspect_surface_ENSTA.cps: )
( inspectionProcessSectionStart, inspectionWriteCycleMove, )
( inspectionProbeTriggerCheck]: G103 P1 [LOOKAHEAD OFF] at the section's )
( start and after each G31, the distance of #5061-#5063 [tool length )
( added back] from the target compared in an IF .. GOTO, and #3000 = 1 )
( [NO POINT TAKEN] when the probe reached the target untouched. )
( Constructs: G103 P1 / G103 P0, G01 safe move, G90 G31 X Y Z F in one )
( block, a G31 that ends without a signal [Haas: no alarm, #5061.. hold )
( the end point], #3000 = 1 with a comment, IF [..] GOTO with N labels. )
( Expected by hand: G54 = X30 Y0 Z-225; the target is the ball centre at )
( work Z-6, 2 below where it meets a nominal surface Z-5; the plate's top )
( [-229.87 = work -4.87] stops it at -3.87. The squared distance from the )
( target is 2.13^2 = 4.5369 > 0.01: the point is taken, no alarm; the )
( surface's deviation #171 = -3.87 - 1 [#556] - [-5] = 0.13. )
G00 G17 G40 G49 G80 G90 G94 G97
G21
G10 L2 P1 X30. Y0. Z-225.
T20 M06
#556 = 1.
G65 P9832
G103 P1 (LOOKAHEAD OFF)
G54 G00 X0. Y0.
G43 H20 Z50.
#120 = 0. (target X)
#121 = 0. (target Y)
#122 = -6. (target Z, the ball centre)
G90 G01 X#120 Y#121 Z[#122 + 3.] F3000.
G90 G31 X#120 Y#121 Z#122 F300.
G103 P1 (LOOKAHEAD OFF)
#131 = #120 - #5061
#132 = #121 - #5062
#133 = #122 - #5063 + #5083
#134 = [#131 * #131] + [#132 * #132] + [#133 * #133]
N20 IF [#134 GT 0.01] GOTO 40
#3000 = 1 (NO POINT TAKEN)
N40 #171 = #5063 - #5083 - #556 - [-5.]
G00 Z50.
G103 P0 (LOOKAHEAD ON)
G65 P9833
G49 G53 G00 Z0.
M30
%
