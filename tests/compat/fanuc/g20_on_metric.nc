%
O1005 (INCH PROGRAM ON A METRIC MACHINE: Z SURFACE INTO G55)
( Compatibility: in the style of the inch programs that Fanuc CAM posts write )
( for US shops [safe-start line G20 G17 G40 G49 G80 G90, the format of the )
( Fusion/Mastercam Fanuc posts] with the probe's data in common variables )
( #500-#501 as the Renishaw-type macros keep them, run on a metric control. )
( Constructs: G20 on a metric machine, G31 Z in inches with F in inch/min, )
( #5063 read in inches, common variables #500.., G10 L2 P2 Z in inches, )
( G55 selected afterwards, no length offset [G49: the gauge line is the )
( programmed point]. )
( Expected by hand [plate top at machine Z -230 mm, ball radius 1 mm, probe )
( 150 mm gauge line to ball centre, G54 = machine]: the ball touches at )
( centre -229 mm, gauge line -79 mm: #5063 = -79 / 25.4 = -3.110236 in. The )
( face: -3.110236 - 5.905512 - 0.039370 = -9.055118 in [-230 mm, #100]. )
( G10 L2 P2 and the Z word take the least input increment, 0.0001 in: G55 Z )
( = -9.0551 in = -229.99954 mm; G55 G0 Z[#500 + 0.5] = Z6.4055 in leaves )
( the gauge line at -229.99954 + 162.6997 = -67.29984 mm, the ball 12.7 mm )
( over the face. )
G20 G17 G40 G49 G80 G90
G91 G28 Z0
G90 G54 G0 X0.5 Y0.5
#500 = 5.905512 (PROBE LENGTH, GAUGE LINE TO BALL CENTRE, INCH)
#501 = 0.039370 (BALL RADIUS, INCH)
G0 Z-2.0
G31 Z-4.0 F10.
#101 = #5063
#100 = #5063 - #500 - #501
G10 L2 P2 Z#100
G91 G0 Z0.1
G90 G55 G0 Z[#500 + 0.5]
M30
%
