%
O20 (THE CYCLES IN AN INCH PROGRAM, G20)
(The machine's G54 is in mm: X-80 Y30.5 Z-229.5. In inches the bore's)
(centre is at G54 X-0.123 / 25.4 = -0.004842520, Y-0.044 / 25.4 =)
(-0.001732283, its diameter 40 / 25.4 = 1.574803150, and the top face at)
(Z-0.37 / 25.4 = -0.014566929. Q, R and the feeds left out take their)
(inch defaults: Q 10 / 25.4 = 0.3937. S1 writes G54 in inches:)
(#5221 = -80.123 / 25.4 = -3.154448819, #5222 = 30.456 / 25.4 =)
(1.199055118, #5223 = -229.87 / 25.4 = -9.050000000.)
(A Fanuc keeps the offsets' numbers in the input unit in force and G20 does)
(not convert them [docs/time-and-units.md]: an inch shop has its G54 and H20)
(in inches, so N12-N15 write the machine file's mm values as inch numbers.)
N10 G20 G90 G17 G40 G49 G80 G54
N12 #5221=-80. / 25.4
N13 #5222=30.5 / 25.4
N14 #5223=-229.5 / 25.4
N15 #11020=151. / 25.4
N20 #550=1. / 25.4
N30 G53 G0 Z0
N40 G43 H20 G0 X0.8 Y-0.8
N50 G65 P9810 Z0.2
N60 G65 P9811 Z0 S1
N70 #101=#137
N80 G65 P9810 Z2.
N90 G0 X0 Y0
N100 G65 P9810 Z-0.4
N110 G65 P9814 D1.5748 S1
N120 #102=#135
N130 #103=#136
N140 #104=#138
N150 G65 P9810 Z2.
N160 M30
%
