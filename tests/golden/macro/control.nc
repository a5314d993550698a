(Control flow: GOTO forward and back, computed GOTO, IF GOTO, IF THEN,)
(WHILE with three nested levels, DO without WHILE left by GOTO)
#1=0
N10#1=#1+1
IF[#1LT3]GOTO10
#140=30
GOTO#140
#2=99 (skipped)
N30#3=0
#4=0
WHILE[#3LT2]DO1
#3=#3+1
#5=0
WHILE[#5LT3]DO2
#5=#5+1
#6=0
WHILE[#6LT4]DO3
#6=#6+1
#4=#4+1
END3
END2
END1
#7=0
DO1
#7=#7+1
IF[#7GE5]GOTO 99
END1
N99 #8=1
IF[#7EQ5]THEN#9=#7*2
GOTO[20+20]
#10=1 (skipped)
N40
M30
