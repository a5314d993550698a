(G28 on a lathe: through the intermediate point, X/Z absolute or U/W)
(incremental, to the reference position [machine zero] of the named axes.)
G50 X100. Z50.
G00 X40. Z2.
G28 U20. (X through 60., Z stays)
G00 X40. Z2.
G28 X50. W0
G00 X40. Z2.
G28 U0 W0
M30
