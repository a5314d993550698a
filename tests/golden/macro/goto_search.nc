(GOTO searches forward from the next block first, then from the top of the)
(program: with two N50, the one after the GOTO wins, else the first one)
#1=0
#2=0
N50#1=#1+1
IF[#1GE3]GOTO70
GOTO50
N50#2=#2+1
GOTO50
N70M98P2000
M30
O2000
(N50 of the main program is not this program's)
#3=1
GOTO 80
#3=2
N80 #4=#3
M99
N50 #3=3
