%
O5009 (PLUNGE GRINDING WITH A MULTI-STEP GAUGE)
(Machine grinder2.machine.toml, scene plunge_grind.scene.toml. One infeed)
(in three steps, each a G31 that the gauge ends: P1 = SKIP1 at 50.3 mm,)
(P2 = SKIP2 at 50.05 mm, P3 = SKIP3 at 50.0 mm; then spark-out.)
(Results: #101-#103 the wheel's X at each step, #104 the final diameter.)
G21 G90 G54
G0 X-70. Z0
G1 X-73.8 F300. (approach the blank: its 52 mm are at X-74.)
G31 P1 X-76. F6. (roughing)
#101 = #5061
G31 P2 X-76. F1. (semi-finishing)
#102 = #5061
G31 P3 X-76. F0.2 (finishing)
#103 = #5061
G04 X2. (spark-out)
#104 = 2 * [#103 + 100.] (the diameter: the work's axis is at X-100.)
G0 X-70.
M30
%
