(GOTO searches forward from the jump, then from the top: N10 is here twice. The first GOTO 10 goes forward to the second N10, the GOTO 10 after it finds none further on and goes to the first; three passes end at N30 with #100 = 3, #101 = 2; N20 never runs)
G21 G90 G54
#100 = 0
#101 = 0
N10 #100 = #100 + 1
IF [#100 GE 3] GOTO 30
GOTO 10
N20 #101 = #101 + 100
N10 #101 = #101 + 1
IF [#101 LT 5] GOTO 10
N30 M30
