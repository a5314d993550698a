(IF needs a comparison, not a value: alarm 114)
#1=1
IF[#1]GOTO10
N10 M30
