%
O1008 (HAAS: SURFACE INSPECTION POINT OVER A HOLE - NO POINT TAKEN)
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
( Expected by hand: G54 = X-80 Y30 Z-225 puts the point over the 40 mm )
( bore at machine -80.123, 30.456 [plate.scene.toml]: the G31 to work )
( Z-6 meets nothing and ends at its end point, no alarm [Haas G31]; )
( #5063 - #5083 = -6, the squared distance is 0 <= 0.01, and the program's )
( own check raises #3000 = 1: alarm 3001 [3000 + 1] at line 40 with the )
( comment as its message; #171 is never written. )
G00 G17 G40 G49 G80 G90 G94 G97
G21
G10 L2 P1 X-80. Y30. Z-225.
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
