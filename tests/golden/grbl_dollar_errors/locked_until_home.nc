( grbl with $22=1 starts in alarm: a G-code line before $H or $X is )
( error:9 [G-code locked out during alarm], at that line. )
G21 G90
M2
