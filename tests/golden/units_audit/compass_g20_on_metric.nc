( Units of stored values, dialect compass [Fanuc family, the rule of )
( fanuc_g20_on_metric.nc]: a G20 program on a metric machine. The work )
( and tool offsets keep their numbers and take the input unit in force: )
( "The unit systems for the following values are changed after inch/metric )
( conversion: ... Workpiece origin offset value, Tool compensation value" )
( [FANUC 30i/31i/32i-A user's manual B-63944EN/02, 8.2]: they are not )
( converted. By hand: G54 X is 10.000, set in mm; under G20 it reads 10.000 )
( [#100] and is 10 inches: G0 X0 goes to machine X 254. H1 = 2.000 reads )
( 2.000 [#101] and G43 H1 Z0 puts Z at machine 2 in = 50.8. G10 L2 P2 X1. )
( under G20 sets 1.000 [#102]; back in G21, #5241 still reads 1.000 [#103] )
( and G55 X0 is machine X 1 mm. )
G20 G90 G54
#100 = #5221
#101 = #11001
G0 X0
#104 = #5021
G43 H1 Z0
#105 = #5023
G10 L2 P2 X1.
#102 = #5241
G21
#103 = #5241
G49 G55 G0 X0
#106 = #5021
M30
