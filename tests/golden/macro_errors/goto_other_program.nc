(GOTO finds only the labels of the running program: alarm 78)
M98 P8000
N20 M30
O8000
#1=1
GOTO20
M99
