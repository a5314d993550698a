(A macro reading the current position under G41 waits for the machine: the held move ends perpendicular to its end point, X5 Y30. #5041 #5042 give the tool centre, with the vector; #5001 #5002 the programmed end point, without it. The next move starts from where the tool is.)
G21 G90 G17 G40 G49
G10 L2 P1 X0 Y0 Z0
G54 G0 X0 Y0 Z0
G10 L12 P1 R5.
G41 D1 X10. Y10.
G1 Y30. F300.
#101 = #5041
#102 = #5042
#103 = #5001
#104 = #5002
X30.
G40 X40.
M30
