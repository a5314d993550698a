(Mitsubishi multi-step skip 2: P5 = skip signal 1 or 3; signal 2 pulses first and is ignored)
G21 G90 G54 G31 Z-50. P5 F600.
M30
