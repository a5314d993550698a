(Mitsubishi multi-step skip function 1: G31.2 skips on the signals of parameter 1177, here 4 = skip signal 3, at the feed of parameter 1178, 600 mm/min; skip signal 1 pulses first and is ignored)
G21 G90 G54 G31.2 Z-50.
M30
