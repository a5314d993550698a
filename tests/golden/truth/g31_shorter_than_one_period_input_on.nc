(A G31 shorter than one servo period with the input already on: at F20000 on a 1 ms)
(period the command covers 0.33 mm per period, more than the 0.2 mm asked. The level)
(input is on at the start, so the block ends with no motion and stores its start)
(point, as a longer block does: #5063 = 0, the machine stays at Z0)
G21 G90 G54
G0 X0 Y0 Z0
G31 Z-0.2 F20000.
#100 = #5063
M30
