(Codes that change nothing in the simulation are accepted: G05.1 Q1, G08 P1, G13.1, G40.1, coolant M08/M09)
G21 G90 G17 F100.
G05.1 Q1
G08 P1
G13.1 G40.1
M8
G0 X1. Y2. Z3.
M9
M30
