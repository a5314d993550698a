(The boss forms of o<probe_three_point> and o<probe_pitch_circle> of)
(macros/probing/linuxcnc, in the linuxcnc dialect on cycles.machine.toml)
(with the five bosses of o9819_bosses.scene.toml [11.98 across, on a 50)
(mm circle centred at G54 X149.93 Y-59.96, turned 3 degrees: the first)
(at 21 degrees], #<_probe_radius> = 1; the values of the Fanuc golden)
(o9819_bosses. 1. o<probe_three_point> boss 1 on the second boss from)
(its nominal centre X150 Y-35 at Z15, touched at Z3 from 5 outside at 0,)
(120, 240 degrees: #100 = 148.621601094, #101 = -34.994261631, #102 =)
(11.98. 2. o<probe_pitch_circle> boss 1 from X150 Y-60, A18, five bosses)
(D12 on C50, touched at Z3 from 5 outside, p 1: #103 = 149.93, #104 =)
(-59.96, #105 = 11.98, #106 = 50, #107 = 21; G54 X -80 - 0.07 = -80.07,)
(Y 30.5 + 0.04 = 30.54. LinuxCNC samples the probe once a servo period,)
(1 ms: each touch up to 0.00167 mm late, a centre or a size up to twice)
(that: within 0.004; the first boss's angle within ATAN[0.0067 / 25] =)
(0.016 degree.)
G21 G90 G17 G40 G49 G80 G54
#<_probe_radius> = 1
G53 G0 Z0
G43 H20
G0 X150 Y-35
o<probe_move> call [150] [-35] [15] [3000]
o<probe_three_point> call [12] [0] [120] [240] [5] [0] [1] [3] [5]
#100 = #<_probe_x>
#101 = #<_probe_y>
#102 = #<_probe_size>
o<probe_move> call [150] [-60] [15] [0]
o<probe_pitch_circle> call [18] [5] [50] [12] [3] [5] [1] [1] [5]
#103 = #<_probe_x>
#104 = #<_probe_y>
#105 = #<_probe_size>
#106 = #<_probe_pcd>
#107 = #<_probe_angle>
o<probe_move> call [150] [-60] [50] [0]
M2
