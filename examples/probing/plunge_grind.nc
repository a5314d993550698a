%
O5009 (PLUNGE GRINDING WITH A MULTI-STEP GAUGE)
(Machine: the built-in grinder2 [-m grinder2], a lathe-type machine with X)
(in diameter; scene plunge_grind.scene.toml. One infeed in three steps,)
(each a G31 that the in-process gauge ends: P1 = SKIP1 at 50.3 mm,)
(P2 = SKIP2 at 50.05 mm, P3 = SKIP3 at 50.0 mm; then spark-out, retract.)
(Results: #101-#103 the diameter at each step's latch, #104 after spark-out.)
G21 G54 G98 (feed per minute for the infeed)
S150 M03 (work spindle)
G0 X60. Z0
G1 X52.4 F300. (approach the blank: 52 mm)
G31 P1 X48. F6. (roughing until SKIP1)
#101 = #5061
G31 P2 X48. F1. (semi-finishing until SKIP2)
#102 = #5061
G31 P3 X48. F0.2 (fine until SKIP3)
#103 = #5061
G04 X2. (spark-out)
#104 = #5001
G0 X60.
M05
M30
%
