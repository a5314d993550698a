(G50 on a lathe: X Z set the present position, U W shift it; S is the)
(G96 speed clamp and does not change the spindle speed.)
G50 X100. Z50.
#101 = #5001
G50 U-10. W5. S1500
#102 = #5001
#103 = #5002
G00 X40.
#104 = #5021 (machine X in diameter: [40 - 90] = -50.)
M30
