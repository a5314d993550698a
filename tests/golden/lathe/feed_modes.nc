(G99 feed per revolution times the spindle speed; G98 feed per minute.)
G50 X100. Z50.
G97 S500 M03
G99 G01 Z40. F0.2
G98 Z30. F150.
G99 Z20. F0.3
S1000
Z10.
M04
Z0
M30
