(TAN of 90 degrees is SIN/COS with COS = 0: alarm 112)
#1=TAN[270.]
M30
