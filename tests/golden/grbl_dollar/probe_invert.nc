( grbl's $6 = 1 inverts the probe pin [Grbl v1.1 Configuration]. The switch )
( of the scene is open at the start [machine Z-5, it closes below Z-20.5], )
( so with the pin inverted the probe reads as in contact before G38.2 moves: )
( ALARM:4 [probe not in the expected initial state], at the G38.2. )
G21 G90
G53 G0 X-100 Y-100 Z-5
$6=1
G38.2 Z-50 F100
M2
