( grbl's $# [Grbl v1.1 Commands]: the work offsets, G28, G30, G92, the tool )
( length offset and the last probe, in mm with 3 decimals; after $13=1 in )
( inches with 4 [the values are kept in mm: only the report changes]. )
( By hand: at machine X-100 Y-50 Z-5, G10 L20 P1 X0 Y0 Z0 makes G54 )
( -100,-50,-5; G28.1 stores that point; 10 mm along X [machine X-90] G30.1 )
( stores -90,-50,-5 and G92 X0 makes the G92 offset X 10 [work X was 10]. )
( G43.1 Z2.5 is the TLO. The switch closes at machine Z-20.5 [scene]: )
( [PRB:-90.000,-50.000,-20.500:1]. Inches: -100/25.4 = -3.9370, -50/25.4 = )
( -1.9685, -5/25.4 = -0.1969, -10/25.4 = -0.3937, -20/25.4 = -0.7874, )
( -30/25.4 = -1.1811, -90/25.4 = -3.5433, 2.5/25.4 = 0.0984, )
( -20.5/25.4 = -0.8071. )
G21 G90
G53 G0 X-100 Y-50 Z-5
G10 L20 P1 X0 Y0 Z0
G10 L2 P2 X-10 Y-20 Z-30
G28.1
G0 X10
G30.1
G92 X0
G43.1 Z2.5
G38.2 Z-50 F100
$#
$13=1
$#
M2
