(G02/G03 on a lathe: G18 at power-on, X in diameter, R, I and K in radius.)
(A quarter circle R5 from X40. Z0 to X50. Z-5., by R and by I K.)
G50 X100. Z50.
G97 S500 M03
G00 X40. Z0
G98 G03 X50. Z-5. R5. F100.
G00 X40. Z0
G03 X50. Z-5. I0 K-5.
G00 X40. Z0
G02 U10. W-5. R5.
M30
