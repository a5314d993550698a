(Tool nose radius compensation is not simulated: a move under G42 with a nose radius of 0.8 on offset 1 is refused in words, not run on the programmed path)
G50 X100. Z50.
G10 P1 R0.8
T0101
M3 S500
G42 G1 X40. Z0 F0.2
M30
