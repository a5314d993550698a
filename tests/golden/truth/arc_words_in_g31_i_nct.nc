(Arc words in a G31 block, NCT: I in a G31 block is refused with alarm 3051)
G21 G90 G54
G0 X0 Y0 Z0
G31 X10. I5. F100.
M30
