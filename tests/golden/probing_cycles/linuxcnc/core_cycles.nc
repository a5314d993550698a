(The LinuxCNC probing subroutines of macros/probing/linuxcnc, run in the)
(linuxcnc dialect on cycles.machine.toml [G54 X-80 Y30.5 Z-229.5, H20 151])
(with the plate of part.scene.toml, ideal probe, #<_probe_radius> = 1.)
(1. The bore, its centre at machine X-80.123 Y30.456: from G54 X0 Y0 at)
(Z-10, o<probe_bore> with p 1: #100 = -0.123, #101 = -0.044, #102 = 40;)
(G54 becomes X-80.123 Y30.456: #5221, #5222.)
(2. The boss, machine X60.789 Y-40.321, in the new G54 X60.789 + 80.123 =)
(140.912, Y-40.321 - 30.456 = -70.777; from X141 Y-70.8 Z25, touched at)
(Z15 from 5 outside: #103 = 140.912, #104 = -70.777, #105 = 30.)
(3. The top face, machine Z-229.87, from X20 Y-20 Z5 down with p 1:)
(#106 = -229.87 + 229.5 = -0.37, #107 = -0.37; G54 Z = -229.87: #5223.)
(4. The pocket across X, machine X-40.25..10.35, centre -14.95: G54)
(X65.173, from X65 Y-90.456 Z-10: #108 = 65.173, #109 = 50.6, #110 =)
(0.173. 5. The web along Y, machine Y20..80: G54 centre 50 - 30.456 =)
(19.544, from X186.573 Y19.5 Z25, touched at Z15 from 5 outside: #111 =)
(19.544, #112 = 60. 6. A protected move from X80 Y0 Z20 toward Y50 meets)
(the clamp, machine Y60, G54 Y29.544, with the ball at 28.544: the run)
(ends with PATH OBSTRUCTED. LinuxCNC samples the probe input once a servo)
(period, 1 ms: a touch at the slow 100 mm/min reads up to 100 / 60000 =)
(0.00167 mm past the surface, a size read from two touches up to twice)
(that: every value is checked within 0.004.)
G21 G90 G17 G40 G49 G80 G54
#<_probe_radius> = 1
G53 G0 Z0
G43 H20
G0 X0 Y0
o<probe_move> call [0] [0] [-10] [1000]
o<probe_bore> call [40] [5] [1]
#100 = #<_probe_x>
#101 = #<_probe_y>
#102 = #<_probe_size>
o<probe_move> call [0] [0] [25] [0]
G0 X141 Y-70.8
o<probe_bore> call [30] [5] [0] [1] [15] [5]
#103 = #<_probe_x>
#104 = #<_probe_y>
#105 = #<_probe_size>
G0 X20 Y-20
o<probe_move> call [20] [-20] [5] [0]
o<probe_surface> call [3] [0] [5] [1]
#106 = #<_probe_pos>
#107 = #<_probe_error>
o<probe_move> call [20] [-20] [25] [0]
G0 X65 Y-90.456
o<probe_move> call [65] [-90.456] [-10] [0]
o<probe_pocket> call [1] [50.6] [5] [0]
#108 = #<_probe_pos>
#109 = #<_probe_size>
#110 = #<_probe_error>
o<probe_move> call [65] [-90.456] [25] [0]
G0 X186.573 Y19.5
o<probe_pocket> call [2] [60] [5] [0] [1] [15] [5]
#111 = #<_probe_pos>
#112 = #<_probe_size>
G0 X80 Y0
o<probe_move> call [80] [0] [20] [0]
o<probe_move> call [80] [50] [20] [0]
M2
