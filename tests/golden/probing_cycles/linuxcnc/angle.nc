(o<probe_angle> of macros/probing/linuxcnc, run in the linuxcnc dialect)
(on cycles.machine.toml [G54 X-80 Y30.5 Z-229.5, H20 151] with the block)
(of o9843_plane_angle.scene.toml, 2 degrees off square, #<_probe_radius>)
(= 1; the same touches as the Fanuc golden o9843_plane_angle. The left)
(face runs at 92 degrees, the front face at 2: two touches on a straight)
(face are offset from it alike, so the line through them has its angle.)
(X face, spacing 30: #100 = 92, #101 = 92 - 90 = 2. Y face, spacing 40,)
(nominal angle 0: #102 = 2, #103 = 2; its first touch at G54 X0: the face)
(at machine Y-50 + 20 TAN2, the ball's centre 1 / COS2 below it, the)
(surface read as its centre + 1: #104 = -50 + 20 TAN2 - 1 / COS2 + 1 -)
(30.5 = -79.802194154. LinuxCNC samples the probe once a servo period:)
(each touch reads up to 0.00167 mm past the face, the angle up to)
(0.0033 / 30 rad = 0.0064 degree off: checked within 0.007.)
G21 G90 G17 G40 G49 G80 G54
#<_probe_radius> = 1
G53 G0 Z0
G43 H20
G0 X-30 Y-70.5
o<probe_move> call [-30] [-70.5] [0] [3000]
o<probe_angle> call [1] [-20.35] [30] [0] [5]
#100 = #<_probe_angle>
#101 = #<_probe_angle_error>
o<probe_move> call [-30] [-70.5] [30] [0]
G0 Y-90
G0 X0
o<probe_move> call [0] [-90] [0] [0]
o<probe_angle> call [2] [-79.8] [40] [0] [5]
#102 = #<_probe_angle>
#103 = #<_probe_angle_error>
#104 = #<_probe_pos>
M2
