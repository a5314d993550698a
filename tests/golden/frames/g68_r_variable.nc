(The probing idiom: the angle measured in a variable, G68 R#100; R without decimal point is in 0.001 degree; R omitted takes parameter 5410, 0)
G21 G90 G17 G54
G0 X0 Y0 Z5.
#100 = 180.
G68 X0 Y0 R#100
G0 X10. Y5.
G68 X0 Y0 R-90000
G0 X10. Y5.
G68 X0 Y0
G0 X10. Y5.
G69
M30
