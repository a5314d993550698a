(T code on a lathe: T0101 = tool 1 with geometry offset 1 and wear offset 1.)
(Offset 1: X 10. [diameter] Z -20.; wear 1: X -0.2 Z 0.05; wear 2: X 0.4.)
(The offset shifts the coordinates; the next move takes the tip there.)
G50 X100. Z50.
T0101
#101 = #5001 (X after T0101, before a move)
G00 X60. Z10.
T0100 (wear cancelled: the tip would be 0.2 mm larger in diameter)
#102 = #5001
U0 W0 (an incremental move carries the change)
#103 = #5001
T0102
X60.
T0
#104 = #5001
M30
