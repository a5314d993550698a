(G cannot be a macro argument: alarm 129)
G65 P8100 G01 X1.
M30
O8100
M99
