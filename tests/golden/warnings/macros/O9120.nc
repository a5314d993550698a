O9120 (probe down to Z#26 and keep the touch in #100)
G31 Z#26 F100.
#100 = #5063
M99
