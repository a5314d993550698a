(A jump into a loop from outside: its END finds no DO, alarm 124)
GOTO10
WHILE[#1LT2]DO1
N10 #1=#1+1
END1
M30
