(A feed into the stock with the spindle stopped, no M03: alarm 9062 where)
(the tip meets the stock's top, the gauge line at machine Z-100, line 7.)
G21 G90 G54
T2 M06
G43 H2 G0 Z20.
G0 X30. Y20.
G1 Z-1. F300.
M30
