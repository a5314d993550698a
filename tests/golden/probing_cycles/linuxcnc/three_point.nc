(o<probe_three_point> of macros/probing/linuxcnc, run in the linuxcnc)
(dialect on cycles.machine.toml with the plate of part.scene.toml: its)
(bore, 40 across, centre at machine X-80.123 Y30.456, G54 X-0.123)
(Y-0.044. From G54 X0 Y0, 10 mm down, touches at 30, 150 and 270)
(degrees: #100 = -0.123, #101 = -0.044, #102 = 40; p 1: G54 X)
(-80.123, Y30.456 [#5221, #5222]. Within 0.004: LinuxCNC samples the)
(probe once a servo period, each touch up to 0.00167 mm late.)
G21 G90 G17 G40 G49 G80 G54
#<_probe_radius> = 1
G53 G0 Z0
G43 H20
G0 X0 Y0
o<probe_move> call [0] [0] [-10] [3000]
o<probe_three_point> call [40] [30] [150] [270] [5] [1]
#100 = #<_probe_x>
#101 = #<_probe_y>
#102 = #<_probe_size>
o<probe_move> call [0] [0] [50] [0]
M2
