(Brackets nest 5 deep at most, a function's own bracket included: alarm 118)
#1=SIN[[[[[#2+1]*2]+1]*2]+1] (5 levels: accepted)
#1=[[[[[[1]]]]]] (6 levels)
M30
