( grbl's $J= [Grbl v1.1 Jogging]: a G1 in the jog's own G20/G21, G90/G91 )
( and G53, at its own F; the program's modes are as they were after it. )
( By hand: G1 X-60 F300 leaves G1, G90, G21, F300. $J=G91 G20 X1 F10 moves )
( X by 1 inch [25.4 mm] to -34.6; $G still reads G1 G21 G90 F300; the next )
( bare X-70 is a G1 in mm, absolute: machine X-70. $J=G53 Y-5 goes to )
( machine Y-5 [G54 is zero here anyway]. )
G21 G90 G54
G0 X-50 Y-50 Z-10
G1 X-60 F300
$J=G91 G20 X1 F10
$G
X-70
$J=G53 Y-5 F500
$G
M2
