(WHILE whose condition is false and no END 1 after it: alarm 124 at the WHILE)
#1=0
WHILE[#1GT0]DO1
#1=#1+1
END2
M30
