(Vacant variables, Fanuc rules: alone it stays vacant, in arithmetic it is 0,)
(in a word the word is omitted, and only EQ and NE tell it from 0)
G21 G90 G54
G0 X10. Y20. Z30.
#1=#0
#2=#1
#3=#1*5
#4=#1+#1
#5=-#1
#6=#[#1] (#[vacant] is #0)
#7=[#1]
IF[#1EQ#0]THEN#10=1
IF[#1NE0]THEN#11=1
IF[#1GE#0]THEN#12=1
IF[#1GT0]THEN#13=1
IF[#1EQ0]THEN#14=1
IF[#1LT0.001]THEN#15=1
#20=0
IF[#20EQ#0]THEN#16=1
IF[#20NE0]THEN#17=1
IF[#20GE#0]THEN#18=1
G90 X100. Y#1 (Y omitted: only X moves)
G1 X50. Z#0 F1000.
M30
