(G04 in revolutions [3405#1 = 1] with the spindle stopped: SN9023)
G99 G04 X2.
M30
