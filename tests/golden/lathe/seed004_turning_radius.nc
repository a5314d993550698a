%
O0023 (SEED 004 EXAMPLE 2-3: FS-0iTD, G-CODE SYSTEM A)
(G50 sets the workpiece coordinate system at the start point, absolute X/Z,)
(X in radius: lathe2 with 1006#3 = 0, spindle 500 r/min, feed 0.2 mm/r.)
N10 G50 X100. Z100.
N20 G97 S500 M03
N30 G99
N40 G00 X20. Z2.
N50 G01 Z-30. F0.2
N60 X30. Z-50.
N70 Z-80.
N80 X41.
N90 G00 X100. Z100.
N100 G28 U0 W0
N110 M05
N120 M30
%
