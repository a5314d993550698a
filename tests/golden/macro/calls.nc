(Calls: M98 with L and the Pxxxxyyyy form, M99 and M99 P, G65 with a local)
(level per call, G65 L, commons shared by all levels, a program on the)
(include path [the file O7001 in this folder] called by M98 P[#891])
#100=0
M98 P7100 L3
M98 P27100 (two more times: P = repetitions then a 4-digit program number)
#1=5.
G65 P7200 A1. B2.
#102=#1 (the macro's #1 was its own)
G65 P7200 L2 A1. B2. (L2: the second run sees the level as the first left it)
M98 P7300
N50 #104=1 (skipped by M99 P60)
N60 #105=1
#891=7001.
M98 P[#891]
M30
O7100
#100=#100+1
M99
O7200
#101=#1+#2
#103=#103+1
#1=99.
M99
O7300
#108=#1 (M98 opens no local level: the caller's #1)
M99 P60
