(spec/cli.md contract: G31 to a trigger plane at Z-3, then an incremental block from the stop)
G21 G90 G54
G0 X0 Y0 Z0
G31 Z-10. F100.
G91 G1 Z5. F500.
M30
