(A warning raised inside a macro names the macro's file, its O number and the call)
G21 G90 G54
G0 X0 Y0 Z0
G65 P9120 Z-5.
M30
