( Compatibility: in the style of fellesverkstedet/fabricatable-machines )
( humphrey-large-format-cnc/humphrey_v2/Settings_backup/home_and_probe_grbl.gcode: )
( home, put the work origin a fixed distance from home with G92, probe the )
( bed twice [fast, then slow] and set Z from the touch with G92, as a grbl )
( start file does. The numbers are this machine's: its home switches are )
( at the top of each axis [grbl3], so the origin and the probing point lie )
( below them. )
( Constructs: $H first [the machine file sets $22 = 1: grbl starts locked], )
( G92 with three axes, G38.2 with F before the axis word, G92 Z0 at the )
( probe's stop, G0 back-off, the second slow probe, G92 Z47 at a height. )
( Scene: the bed at machine Z -80. )
( Expected by hand: $H ends at machine -1,-1,-1 [$27 = 1 mm]; G92 X-10.5 )
( Y37 Z0 there makes the G92 offset X 9.5, Y -38, Z -1 [machine - work]; )
( G0 X-120 Y-20 goes to machine X -110.5, Y -58. Both touches latch Z -80: )
( [PRB:-110.500,-58.000,-80.000:1]. G92 Z0 at each stop, G0 Z40 up from the )
( second, G92 Z47 there: the run ends at work Z 47 exactly, machine Z -40 )
( less the slow stop's micrometres [tolerance 0.01]. )
$H
G92 X-10.5 Y37 Z0
G0 X-120 Y-20
G38.2 F300 Z-130
G92 Z0
G0 Z2
G38.2 F50 Z-5
G92 Z0
G0 Z40
G92 Z47
M2
