(CompassNC's own manual example saves the latch in #1001, a user variable of that)
(control; skipnc keeps #100-#199 and #500-#999, so #1001 is refused by its number)
(with alarm SN9042 at the block, after the G31 ran: docs/skip-dialects.md)
N1 G90 G17 G21
N10 G0 X0.0 Y0.0 Z0.0 F12000
N12 G31 X100 F200 // skip move
#1001 = # <NC.SysVars.G31.LCS.X> // refused: no #1001 here
M30
