( A false if whose endif is missing: the file ends while looking for it. )
o1 if [0]
G0 X1
M2
