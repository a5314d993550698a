(F30000 on a move along X: the built-in mill's X max_feed is 20000 mm/min, so the move runs at 20000 and the report says so)
G21 G90 G54
G0 X0 Y0 Z0
G1 X50. F30000.
M30
