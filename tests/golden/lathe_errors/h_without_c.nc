(H is the incremental C: refused on a lathe without a C axis)
G50 X100. Z50.
G00 X50. H10.
M30
