(G90 on a lathe is the turning cycle of system A, not absolute mode)
G50 X100. Z50.
G90 U-10. W-20. F0.2
M30
