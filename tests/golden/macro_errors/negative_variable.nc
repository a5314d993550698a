(A negative variable number: alarm 115)
#1=-3
#2=#[#1]
M30
