(An endless loop ends at limits.max_macro_statements of the machine file)
#1=0
WHILE[1EQ1]DO1
#1=#1+1
END1
M30
