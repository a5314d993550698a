%
O1010 (HAAS: PROTECTED MOVE STOPPED BY A CLAMP - G65 P9810 X.. F..)
( Compatibility: in the style of the protected positioning moves )
( Autodesk's "HAAS - Next Generation Control" post writes between probe )
( cycles [ThomasLeMezo/enstabretagne-inventor-cam, postpro/haas_vf2_ )
( inspect_surface_ENSTA.cps, protectedProbeMove: G65 P9810 X.. Y.. F..], )
( which stop the machine when the probe is touched on the way. )
( Constructs: G65 P9810 X Y F at the post's high feed, a G31 that touches )
( before its end, the macro's check of #5061 against the target, #3000 = )
( 91 [PATH OBSTRUCTED] from inside a macro. )
( Expected by hand: G54 is zero; the probe [ball centre at Z-200] runs )
( along Y75 from X-40 toward X40 through the clamp [plate.scene.toml: X )
( -10..10, Y 60..90, up to Z-190]: the ball touches the clamp's -X face )
( with its centre at X-11, the G31 stops there, and O9810 finds #5061 = )
( -11 short of the target 40: alarm 3091 [3000 + 91] PATH OBSTRUCTED, in )
( O9810.nc at its line 18; the axes rest just past -11 [decelerating stop]. )
G00 G17 G40 G49 G80 G90 G94 G97
G21
T20 M06
#556 = 1.
G65 P9832
G54 G00 X-40. Y75.
G43 H20 Z-150.
G65 P9810 Z-200. F3000.
G65 P9810 X40. Y75. F3000.
G65 P9810 Z-150. F3000.
G65 P9833
G49 G53 G00 Z0.
M30
%
