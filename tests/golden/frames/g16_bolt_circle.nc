(G16 polar coordinates with G81: X is the radius, Y the angle about the work origin; three holes on a 50 mm radius)
G21 G90 G17 G54 F100.
G0 X0 Y0 Z10.
G16
G99 G81 X50. Y0 Z-5. R2.
Y90.
Y180.
G80 G15
G0 X0 Y0
M30
