(G37.1 is Mitsubishi's automatic tool length measurement [M700V/M70V)
(programming manual 15.1]: a code of that control that skipnc does not)
(simulate, refused by name [SN9024], not as an improper G code)
G21 G90 G17 G54
G43 H1 G0 Z50.
G37.1 Z0 R10. D2. F100.
M30
