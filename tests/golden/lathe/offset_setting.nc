(G10 on a lathe: P10001 = geometry offset 1, P1 = wear offset 1; X Z set,)
(U W add. The values of tool_offsets.machine.toml, written by the program;)
(the offset takes effect at the next T code.)
G50 X100. Z50.
G10 P10001 X10. Z-20. R0.4 Q3
G10 P1 X-0.1 Z0.05
G10 P1 U-0.1
G00 X60. Z10.
#101 = #5001 (no T yet: 60.)
T0101
#102 = #5001 (60. - 9.8 = 50.2)
X60. Z10.
M30
