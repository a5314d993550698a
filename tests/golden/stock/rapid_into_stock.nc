(A rapid into the stock: T2 turns, but G00 does not cut. Its tip meets)
(the stock's top, G54 Z0, with the gauge line 100 mm above it: alarm 9062)
(at machine X-70 Y-30 Z-100, line 9.)
G21 G90 G54
T2 M06
S3000 M03
G43 H2 G0 Z20.
G0 X30. Y20.
G0 Z-1.
M30
