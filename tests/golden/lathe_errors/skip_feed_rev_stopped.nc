(G31 in G99 with the spindle stopped: SN9023)
G50 X100. Z50.
G31 U-10. F0.2
M30
