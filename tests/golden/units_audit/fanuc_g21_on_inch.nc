( Units of stored values, Fanuc: a G21 program on an inch machine [the rule )
( of fanuc_g20_on_metric.nc, B-63944EN/02 8.2]. By hand: G54 X is 1.0000 )
( and H1 2.0000, set in inches; under G21 they read 1.0 and 2.0 [#100, )
( #101] and are millimetres: G0 X0 goes to machine X 1 mm [#104 = 1.0], )
( G43 H1 Z0 to machine Z 2 mm [#105]. G10 L2 P1 X3. under G21 sets 3.0; )
( back in G20 it is 3 inches: G0 X0 goes to machine X 76.2 mm [#106 = 3.0 )
( inches]. )
G21 G90 G54
#100 = #5221
#101 = #11001
G0 X0
#104 = #5021
G43 H1 Z0
#105 = #5023
G10 L2 P1 X3.
G20
G49 G0 X0
#106 = #5021
M30
