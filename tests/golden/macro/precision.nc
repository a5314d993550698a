(Precision: IEEE double arithmetic, and EQ/NE compare exactly, without a)
(tolerance, as Fanuc 15i/30i manuals state: 0.1+0.2 is not 0.3)
#1=0.1+0.2
IF[#1EQ0.3]THEN#2=1
IF[#1NE0.3]THEN#3=1
IF[ABS[#1-0.3]LT0.000001]THEN#4=1
#5=1/3*3
IF[#5EQ1]THEN#6=1
M30
