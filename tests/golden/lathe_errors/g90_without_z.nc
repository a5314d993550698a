(The first G90 cycle block needs the end of the cut in Z: Z or W)
G50 X100. Z50.
G97 S500 M03
G00 X60. Z2.
G99 G90 U-10. F0.2
M30
