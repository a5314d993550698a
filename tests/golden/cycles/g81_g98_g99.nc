(G81: rapid to R, feed to Z, rapid back to the initial level in G98 and to R in G99)
G21 G90 G17 G54 F200.
G0 X0 Y0 Z50.
G98 G81 X10. Y20. Z-10. R2.
G99 X30.
Y40.
G80
G0 Z50.
M30
