(Operators of Custom Macro B and their precedence: functions, then * / MOD AND,)
(then + - OR XOR, then EQ NE GT GE LT LE; brackets nest 5 deep)
#1=7.5+2.25
#2=7.5-10
#3=-2.5*4
#4=7/2
#5=10MOD3
#6=-10MOD3
#7=12AND10
#8=12OR10
#9=12XOR10
#10=2+3*4
#11=[2+3]*4
#12=1+12AND10
#13=[[[[[1+1]*2]+1]*2]+1] (five levels of brackets)
#14=--3
#15=2*-#3
#16=6/4*2
#17=10.7MOD3
#18=1OR2*4
#19=[1LT2]+[3GE3]+[2EQ2.]+[1NE1]+[2LE1]+[2GT1]
M30
