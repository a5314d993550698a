(Z and W in one block)
G50 X100. Z50.
G00 W-5. Z10.
M30
