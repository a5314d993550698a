( Units of stored values, grbl: grbl keeps every offset in mm, its internal )
( unit, whatever G20/G21 is in force [grbl 1.1 gcode.c converts each inch )
( value to mm as it reads it]; $13=1 "report in inches" changes only what )
( $# and [PRB:] print [Grbl v1.1 Configuration, $13]: the nearest grbl has )
( to an inch machine. By hand: G10 L2 P1 X25.4 under G21 is 25.4 mm: $# )
( with $13=1 prints 1.0000; G20 G10 L2 P2 Y-1 stores -25.4 mm; G20 G28.1 )
( at machine Z -12.7 stores -12.7 mm: [G28:0.0000,0.0000,-0.5000]; back )
( in G21, G55 G0 Y0 goes to machine Y -25.4. )
$13=1
G21 G10 L2 P1 X25.4
G20 G10 L2 P2 Y-1
G53 G0 Z-0.5
G28.1
$#
G21 G55 G0 Y0
M2
