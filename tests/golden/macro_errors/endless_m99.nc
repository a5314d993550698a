(M99 in the main program starts it again: endless, until the statement limit)
#100=#100+1
M99
