(A lathe with a C axis: C absolute, H incremental, in degrees.)
G50 X100. Z50. C0
G98 G01 C90. F1000.
H-45.
X80. H30.
M30
