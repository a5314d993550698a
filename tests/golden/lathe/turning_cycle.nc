(G90 on a lathe [G-code system A] is the outer-diameter cutting cycle, not)
(absolute mode: X/Z give the end point absolutely, U/W incrementally from)
(the start point. Three passes from X60. Z2.: X50., X45. [Z modal], then)
(U-20. W-22. [to X40. Z-20.]; then a taper pass with R-2.5 [radius].)
G50 X100. Z50.
G97 S500 M03
G00 X60. Z2.
G99 G90 X50. Z-20. F0.2
X45.
U-20. W-22.
X40. Z-20. R-2.5
G00 X100. Z50.
M30
