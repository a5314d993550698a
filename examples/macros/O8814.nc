%
O8814 (BORE CENTRE AND DIAMETER)
(G65 P8814 D.. S..  with the probe inside the bore, at the measuring depth.)
(D: nominal bore diameter. S: work offset to set, 1-6 = G54-G59, omitted: none.)
(#500: effective diameter of the stylus ball, from calibration.)
(Results: #135 X centre, #136 Y centre, #138 diameter; work coordinates.)
IF[#7EQ#0]THEN#3000=92(DIAMETER D MISSING)
IF[#500EQ#0]THEN#3000=95(STYLUS NOT CALIBRATED)
#10=#5001 (start: the nominal centre)
#11=#5002
#12=#7/2-#500/2+5. (search distance: to the wall and 5 mm beyond)
#13=1
WHILE[#13LE2]DO1
(X when #13 = 1, Y when #13 = 2)
#15=#[9+#13] (start of this axis)
G91 G31 X[#12*[2-#13]] Y[#12*[#13-1]] F500.
#16=#[5060+#13] (touch in +)
IF[ABS[#16-#15-#12]LT0.001]GOTO93
G90 G0 X#10 Y#11
G91 G31 X[-#12*[2-#13]] Y[-#12*[#13-1]] F500.
#17=#[5060+#13] (touch in -)
IF[ABS[#15-#17-#12]LT0.001]GOTO93
#[9+#13]=[#16+#17]/2 (the centre on this axis)
#[19+#13]=#16-#17+#500 (the diameter on this axis)
G90 G0 X#10 Y#11
#13=#13+1
END1
#135=#10
#136=#11
#138=[#20+#21]/2
IF[#19EQ#0]GOTO10
IF[[#19LT1]OR[#19GT6]]THEN#3000=94(S MUST BE 1 TO 6)
#30=5201+ROUND[#19]*20 (the X variable of the work offset)
#[#30]=#[#30]+#10
#[#30+1]=#[#30+1]+#11
N10M99
N93#3000=93(NO BORE EDGE FOUND)
%
