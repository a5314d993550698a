(GOTO outside 1..99999: alarm 128)
#1=0
GOTO#1
M30
