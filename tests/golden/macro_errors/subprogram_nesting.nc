(M98 nests 10 levels deep: the eleventh call, alarm 77)
M98 P8300
M30
O8300
#100=#100+1
M98 P8300
M99
