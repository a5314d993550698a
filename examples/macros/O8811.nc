%
O8811 (SINGLE SURFACE IN Z)
(G65 P8811 Z.. S..  with the probe above the surface.)
(Z: where the surface should be, work coordinates. S: work offset to set,)
(1-6 = G54-G59, so that the surface is at Z; omitted: none.)
(Results: #137 measured Z, #141 error: measured - nominal.)
IF[#26EQ#0]THEN#3000=92(Z MISSING)
#10=#5003 (start)
G90 G31 Z[#26-10.] F1000. (fast, down to 10 mm below the nominal surface)
#12=#5083 (the length offset: #5063 has it in it)
IF[ABS[#5063-#12-[#26-10.]]LT0.001]GOTO93
G91 G0 Z2.
#11=#5003
G31 Z-4. F50. (slow: the measurement)
IF[ABS[#5063-#12-[#11-4.]]LT0.001]GOTO93
#137=#5063-#12
#141=#137-#26
G90 G0 Z#10
IF[#19EQ#0]GOTO10
IF[[#19LT1]OR[#19GT6]]THEN#3000=94(S MUST BE 1 TO 6)
#30=5203+ROUND[#19]*20 (the Z variable of the work offset)
#[#30]=#[#30]+#141
N10M99
N93#3000=93(NO SURFACE FOUND)
%
