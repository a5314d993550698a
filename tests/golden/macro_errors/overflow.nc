(A result that is not a finite number: alarm 111)
#1=EXP[1000.]
M30
