(G31 on lathe2: the skip position in the program's units, X in diameter.)
(The scene's trigger is at machine X-20.: the work's axis is at machine)
(X-50. [G50 X100. at machine 0], so the latch is at diameter 60.)
G50 X100. Z50.
G98 G31 U-80. F100.
#101 = #5061
#102 = #5001
#103 = #5021
G00 X100.
M30
