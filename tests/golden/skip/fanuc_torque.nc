(Torque limit skip: Z pushes against a stop at Z-3 until the torque reaches Q40)
G21 G90 G54 G0 X0 Y0 Z0
G31 P98 Z-10. F300. Q40
G91 G0 Z5.
M30
