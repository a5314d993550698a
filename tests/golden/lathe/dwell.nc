(G04 on a lathe: X and U in seconds with a decimal point, in 1 ms without;)
(P in ms. 3405#1 = 0 on lathe2: seconds even in G99.)
G97 S600 M03
G04 X1.5
G04 U2.
G04 X250
G04 P500
M30
