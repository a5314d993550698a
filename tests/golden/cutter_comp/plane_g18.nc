(G18: compensation in the Z-X plane, seen from +Y, G42 D1 = 2 along a shoulder: the start-up ends at X22 Z0, the inner corner at the intersection X22 Z-18, the cancel of type A perpendicular to the face, X30 Z-18)
G21 G90 G18 G40
G10 L12 P1 R2.
G0 X20. Y0 Z10.
G42 D1 G1 Z0 F200.
Z-20.
X30.
G40 Z-30.
M30
