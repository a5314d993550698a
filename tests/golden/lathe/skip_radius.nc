(G31 on lathe2: the skip position in the program's units, X in radius with 1006#3 = 0.)
(The scene's trigger is at machine X-20.: the work's axis is at machine)
(X-50. [G50 X50. at machine 0], so the latch is at radius 30.)
G50 X50. Z50.
G98 G31 U-40. F100.
#101 = #5061
#102 = #5001
#103 = #5021
G00 X50.
M30
