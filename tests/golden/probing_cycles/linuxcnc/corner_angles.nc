(o<probe_corner> of macros/probing/linuxcnc with a spacing, in the)
(linuxcnc dialect on cycles.machine.toml with the block of)
(o9815_o9816_angles.scene.toml, 2 degrees off square about its)
(front-left corner G54 X0 Y-50, a pocket in it; #<_probe_radius> = 1;)
(the values of the Fanuc golden o9815_o9816_angles. 1. The outer corner)
(from X-6 Y-56, spacing 10: #100 = 0, #101 = -50, #102 = 92 [the X)
(face's angle], #103 = 2 [its error], #104 = 2 [the Y face's]. 2. The)
(pocket's inner corner, nominal X20 Y-35, from X26 Y-29, p 1: #105 =)
(20 COS2 - 15 SIN2 = 19.46432409, #106 = -50 + 20 SIN2 + 15 COS2 =)
(-34.311147661, #107 = -0.53567591, #108 = 0.688852339, #109 = 2; G54)
(X -80.53567591, Y 31.188852339. LinuxCNC samples the probe once a servo)
(period: each touch up to 0.00167 mm late; a face's line then off by up)
(to 0.00167 + 0.6 x 0.0033 = 0.0037 at the corner, 6 mm before its)
(touches 10 apart: within 0.004; an angle within ATAN[0.0033 / 10] =)
(0.019 degree.)
G21 G90 G17 G40 G49 G80 G54
#<_probe_radius> = 1
G53 G0 Z0
G43 H20
G0 X-6 Y-56
o<probe_move> call [-6] [-56] [-5] [3000]
o<probe_corner> call [0] [-50] [5] [0] [1] [10]
#100 = #<_probe_x>
#101 = #<_probe_y>
#102 = #<_probe_angle>
#103 = #<_probe_angle_error>
#104 = #<_probe_y_angle>
o<probe_move> call [-6] [-56] [10] [0]
G0 X26 Y-29
o<probe_move> call [26] [-29] [-5] [0]
o<probe_corner> call [20] [-35] [5] [1] [0] [10]
#105 = #<_probe_x>
#106 = #<_probe_y>
#107 = #<_probe_dx>
#108 = #<_probe_dy>
#109 = #<_probe_angle_error>
o<probe_move> call [26] [-29] [10] [0]
M2
