%
O0001 (BLOCK DELETE: SWITCHES 1 AND 3 ON, PARAMETER 90014 = 5)
G21 G90 G17 G54
G0 X0 Y0 Z5.
/G1 X10. F500 (switch 1, written /: skipped)
/2 G1 Y10. F500 (switch 2 off: run)
/3 G1 X20. F500 (switch 3 on: skipped)
/1 #100 = 7 (skipped: #100 stays vacant)
#101 = [#100 + 1]
G1 X#101 F500
/ 2 G1 Z1. (a blank between / and its number)
M30
%
