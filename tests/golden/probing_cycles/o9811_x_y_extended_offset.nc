%
O2 (O9811 X AND Y: THE PLATE'S RIGHT AND FRONT FACES)
(Right face: machine X150 = G54 X230 [G54 X is -80]. Nominal X230.2, touched)
(going -X from X235: #135 = 230, #140 = 230 - 230.2 = -0.2, #145 = 0.4,)
(#146 = -[-1][-0.2] = -0.2, met late: less metal, #147 = 1; S1: G54 X)
(#5221 = -80 - 0.2 = -80.2. Front face: machine Y-100 = G54 Y-130.5. Nominal)
(Y-130.4, touched going +Y from Y-135: #136 = -130.5, #141 = -0.1; S154.01)
(is G54.1 P1, which starts at 0: its Y #7002 = -0.1; its X #7001 stays 0.)
N10 G21 G90 G17 G40 G49 G80 G54
N20 #550=1.
N30 G53 G0 Z0
N40 G43 H20 G0 X235. Y0
N50 G65 P9810 Z-5. F3000.
N60 G65 P9811 X230.2 Q5. S1.
N70 #101=#135
N80 #102=#140
N90 #103=#145
N100 #104=#146
N110 #105=#147
N120 G65 P9810 Z50.
N130 G0 X0 Y-135.
N140 G65 P9810 Z-5.
N150 G65 P9811 Y-130.4 Q5. S154.01
N160 G65 P9810 Z50.
N170 M30
%
