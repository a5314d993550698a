(o<probe_corner> of macros/probing/linuxcnc, run in the linuxcnc dialect)
(on cycles.machine.toml with the plate of part.scene.toml, the same)
(corners as the Fanuc golden o9815_o9816_corners. Inner: the pocket's +X)
(wall at G54 X90.35, its +Y wall at Y-70.5; from X85 Y-75, 10 mm down,)
(nominal X90.3 Y-70.6, p 1: #100 = 90.35, #101 = -70.5, #102 = 0.05,)
(#103 = 0.1; G54 X -80 + 0.05 = -79.95, Y 30.5 + 0.1 = 30.6 [#5221,)
(#5222]. Outer: the plate's corner, machine X150 Y100, in the corrected)
(G54 at X229.95 Y69.4; from X235 Y75, 5 mm under the top, nominal X230)
(Y69.5: the X face touched at Y2 x 69.5 - 75 = 64, the Y face at X225:)
(#104 = 229.95, #105 = 69.4, #106 = -0.05, #107 = -0.1. Within 0.004:)
(LinuxCNC samples the probe once a servo period, 0.00167 mm at 100)
(mm/min, and the outer corner is read in the G54 the inner one set.)
G21 G90 G17 G40 G49 G80 G54
#<_probe_radius> = 1
G53 G0 Z0
G43 H20
G0 X85 Y-75
o<probe_move> call [85] [-75] [-10] [3000]
o<probe_corner> call [90.3] [-70.6] [5] [1] [0]
#100 = #<_probe_x>
#101 = #<_probe_y>
#102 = #<_probe_dx>
#103 = #<_probe_dy>
o<probe_move> call [85] [-75] [50] [0]
G0 X235 Y75
o<probe_move> call [235] [75] [-5] [0]
o<probe_corner> call [230] [69.5] [5] [0] [1]
#104 = #<_probe_x>
#105 = #<_probe_y>
#106 = #<_probe_dx>
#107 = #<_probe_dy>
o<probe_move> call [235] [75] [50] [0]
M2
