(ASIN outside -1..1: alarm 119)
#1=ASIN[1.5]
M30
