(Warnings, not alarms: G05.1 is accepted and changes nothing in the simulation; the program ends at the end of its file without M30)
G21 G90 G17 G54
G05.1 Q1
G0 X10. Y0 Z5.
