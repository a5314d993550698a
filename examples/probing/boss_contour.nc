%
O5010 (BOSS: CENTRE PROBED, THEN FINISHED WITH G41)
(The boss's centre is probed as in boss_centre.nc, then the end mill T1)
(goes round it once at the measured centre with cutter radius)
(compensation: D1 = 5.1, the tool's 5 mm radius and 0.1 mm of stock.)
(The path runs 20.1 mm from the centre, so the tool misses the boss)
(by 0.1 mm; without compensation it would cut 5 mm into it: a collision.)
(Results: #130 X centre, #131 Y centre, #132 diameter.)
#120 = 1.0 (effective ball radius, from calibration)
G21 G90 G17 G40 G54
G43 H20 G0 Z-200.
G0 X85. Y-40.3
G0 Z-219.87
G31 X60. F300.
#101 = #5061
G0 X85.
G0 Z-200.
G0 X36.
G0 Z-219.87
G31 X60. F300.
#102 = #5061
G0 X36.
G0 Z-200.
#130 = [#101 + #102] / 2
G0 X#130 Y-16.
G0 Z-219.87
G31 Y-40. F300.
#103 = #5062
G0 Y-16.
G0 Z-200.
G0 Y-65.
G0 Z-219.87
G31 Y-40. F300.
#104 = #5062
G0 Y-65.
G0 Z-200.
#131 = [#103 + #104] / 2
#132 = #103 - #104 - 2 * #120
G49 G53 G0 Z0
(Finish: T1, H1 = its length, D1 = radius + stock)
T1 M06
G10 L10 P1 R123.456
G10 L12 P1 R5.1
G0 X[#130 + 40.] Y[#131 + 10.]
G43 H1 Z-200.
Z-225.
(Start-up of type A: ends at X[#130 + 20.1], perpendicular to the lead-in)
G41 D1 G1 X[#130 + 15.] F600.
Y#131
G2 I-15.
G1 Y[#131 - 10.]
G40 X[#130 + 40.]
G0 Z-200.
G49 G53 G0 Z0
M30
%
