( grbl's $110 [X max rate, mm/min] and $120 [X acceleration, mm/s^2] change )
( the moves after them [Grbl v1.1 Configuration]. grbl3: X 5000 mm/min, )
( 400 mm/s^2, no servo lag. By hand, a 300 mm rapid with a trapezoid takes )
( L/v + v/a: 300/83.333 + 83.333/400 = 3.6 + 0.2083 = 3.8083 s; after )
( $110=1000 [16.667 mm/s]: 18 + 0.0417 = 18.0417 s; after $120=50: )
( 18 + 0.3333 = 18.3333 s. Total 40.183 s; the run adds a few )
( servo periods of in-position checks [40.188 s]. )
G21 G90
G53 G0 X-300
$110=1000
G53 G0 X0
$120=50
G53 G0 X-300
M2
