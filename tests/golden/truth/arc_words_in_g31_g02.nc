(Arc words in a G31 block: G31 is a linear move, G02 with it is refused with the)
(dialect's G31 format alarm, not run straight and left modal)
G21 G90 G54
G0 X0 Y0 Z0
G31 G02 X10. R5. F100.
M30
