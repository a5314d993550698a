(G91 with K3: R is the distance from the initial level Z10 to point R Z3, Z the distance from R to the bottom Z-5; each repeat moves by the X increment again)
G21 G90 G17 G54 F100.
G0 X0 Y0 Z10.
G91 G99 G81 X15. Z-8. R-7. K3
G90 G80
M30
