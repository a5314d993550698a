(The corners real macros lean on, as the issue lists them, with the value a)
(Fanuc control gives)
G21 G90 G54
G0 X0 Y0 Z0
#1=#0
G1 X5. Y#1 F1000. (vacant in a word: the word is omitted)
IF[#1EQ0]THEN#100=1 (only EQ/NE tell vacant from 0: not taken)
IF[#1LE0]THEN#101=1 (LE treats vacant as 0: taken)
#102=FIX[-2.5]
#103=FUP[-2.5]
#104=FUP[2.000001]
#2=384
IF[#2AND128EQ0]THEN#105=1 (AND binds tighter than EQ: 384 AND 128 = 128)
IF[#2AND64EQ0]THEN#106=1
#2=1
#[5201+#2*20]=12.5 (G54 X)
#107=#5221
#1=0
#[3006-#1]=1(INDIRECT STOP MESSAGE)
#1=3
#8=1
G#8 X6. (G#8 is G01)
#108=#4001
#140=41
GOTO#140
#109=1 (skipped)
N41#22=50
N42GOTO#22
#110=1 (skipped)
N50#891=7600
M98 P[#891]
G65P7601X0.Y0.A54.
GOTO 9 9 0
#111=1 (skipped)
N990 #112=#1 (the macro's locals are gone: main level again)
#116=#24
M30
O7600
#113=1
M99
O7601
#114=#1 (A54.)
#115=#24
M99
