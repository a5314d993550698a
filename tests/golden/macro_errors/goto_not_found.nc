(GOTO to a sequence number the program does not have: alarm 78)
#1=1
IF[#1EQ1]GOTO500
M30
