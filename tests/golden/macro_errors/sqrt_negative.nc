(SQRT of a negative value: alarm 119)
#1=SQRT[-4.]
M30
