(With parameter 3401#0 DPI = 1 a value without decimal point is in mm:)
(G65 X10 passes 10)
G21
G65 P7800 X10 R5
#110=#100
#111=#103
M30
O7800
#100=#24
#103=#18
M99
