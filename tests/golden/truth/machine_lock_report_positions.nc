(Machine lock: the report's machine positions are where the machine is. Under)
(machine lock the axes stay at machine Z0 while the command runs; a pulse on the)
(skip input comes during the G31. The skip's machine_position, the final machine)
(position and #5023 all say Z0; #5063 holds the command at the signal)
G21 G90 G54
G0 X0 Y0 Z0
G31 Z-10. F600.
#100 = #5023
M30
