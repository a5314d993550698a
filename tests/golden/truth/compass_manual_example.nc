(CompassNC's own manual example, in its style: the G31 page of the CompassNC manual)
(writes comments as // to the end of the line, G52 and G43 P0 before the move, and)
(reads the latch with a space after #; here into #100, as skipnc has no #1001)
N1 G90 G17 G21
N2 G52 X0 Y0 Z0 // local system at the work origin
N3 G43 P0 // no tool length
N10 G0 X0.0 Y0.0 Z0.0 F12000
N12 G31 X100 F200 // skip move in the active system
#100 = # <NC.SysVars.G31.LCS.X> // keep the recorded X
N14 G1 Y100 F12000
G1 X0 Y0
G1 X[#100] // back to the recorded X
M30
