(Mitsubishi: G31 without F and #1174 Skip_F = 0 is program error P603)
G21 G90 G54 G1 X1. F300.
G31 Z-10.
M30
