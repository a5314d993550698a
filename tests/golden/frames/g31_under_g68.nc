(A skip under G68 R90 about the origin: the program +X is the machine +Y. The trigger is at machine Y 17.5; #5061 and #5062 are in the unrotated workpiece coordinates: X0, Y17.5)
G21 G90 G17 G54
G0 X0 Y0 Z0
G68 X0 Y0 R90.
G31 X30. F300.
#101 = #5061
#102 = #5062
G69
M30
