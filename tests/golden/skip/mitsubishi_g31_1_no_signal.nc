(Mitsubishi G31.1 with no skip signal set in parameter 1175: program error P35)
G21 G90 G54 G31.1 Z-50. F100.
M30
