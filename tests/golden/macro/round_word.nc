(An expression in a length word is rounded to 0.001 mm; ROUND in a word)
(rounds to that increment too, so the tool comes back exactly: the)
(manual's example with #1 = 1.2345 and #2 = 2.3456)
G21 G91 G0 X0 Y0
#1=1.2345
#2=2.3456
G0 X-#1 (moves 1.235)
G1 X-#2 F300. (moves 2.346)
G0 X[ROUND[#1]+ROUND[#2]] (3.581: back at X0)
G0 Y-#1
G1 Y-#2
G0 Y[#1+#2] (3.5801 -> 3.580: 0.001 short)
#100=ROUND[#1] (in a macro statement: to a whole number)
G90
M30
