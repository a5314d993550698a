( The grbl dialect on the built-in mill3, a servo machine that lags its )
( command: the run warns once that grbl's position is the command. )
G21 G90
G0 X10
M2
