(G96 constant surface speed with the G50 S clamp: 200 m/min at X100.)
(is 636.6 rpm; at X20. it would be 3183 rpm, clamped to 2000.)
G50 X100. Z50. S2000
G96 S200 M03
G99 G01 Z40. F0.2
G00 X20.
G01 Z30.
G97 S300
Z20.
M30
