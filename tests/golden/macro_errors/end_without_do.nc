(END without its DO: alarm 124)
#1=1
END1
M30
