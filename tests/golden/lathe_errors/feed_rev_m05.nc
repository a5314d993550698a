(The spindle stopped by M05 before a G99 cut: SN9023)
G50 X100. Z50.
G97 S500 M03
G99 G01 W-5. F0.2
M05
W-5.
M30
