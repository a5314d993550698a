(X and U in one block: the same axis absolute and incremental)
G50 X100. Z50.
G00 X50. U-10.
M30
