(o<probe_pitch_circle> of macros/probing/linuxcnc, run in the linuxcnc)
(dialect on cycles.machine.toml with the scene of the Fanuc golden)
(o9819_pitch_circle: four holes 10 across on a circle 60 across, its)
(centre at G54 X100.05 Y-60.47, the first hole at 47 degrees. Called as)
(a 45 from the nominal centre X100 Y-60.5, the holes measured 5 under the)
(top [k -5], p 1: #100 = 100.05, #101 = -60.47, #102 = 10, #103 = 60,)
(#104 = 47; G54 X -80 + 0.05 = -79.95, Y 30.5 + 0.03 = 30.53. Within)
(0.004 mm [0.004 degree]: LinuxCNC samples the probe once a servo period.)
G21 G90 G17 G40 G49 G80 G54
#<_probe_radius> = 1
G53 G0 Z0
G43 H20
G0 X100 Y-60.5
o<probe_move> call [100] [-60.5] [5] [3000]
o<probe_pitch_circle> call [45] [4] [60] [10] [-5] [5] [1]
#100 = #<_probe_x>
#101 = #<_probe_y>
#102 = #<_probe_size>
#103 = #<_probe_pcd>
#104 = #<_probe_angle>
o<probe_move> call [100] [-60.5] [50] [0]
M2
