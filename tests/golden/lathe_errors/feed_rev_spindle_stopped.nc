(G99 feed per revolution with the spindle never started: SN9023)
G50 X100. Z50.
G99 G01 W-10. F0.2
M30
