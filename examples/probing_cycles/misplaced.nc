%
O1002 (A PART SET UP WITH AN UNKNOWN ERROR: THE CYCLES FIND IT)
(For misplaced.sweep.toml: each scenario replaces G54 X Y Z, set up 0.5)
(mm or less off; the program touches the top face with O9811 S1 and the)
(bore with O9814 S1, and G54 ends where the part is, whatever it was:)
(#5221 = -80.123, #5222 = 30.456, #5223 = -229.87 with the ideal probe.)
N10 G21 G90 G17 G40 G49 G80 G54
N20 IF[#550EQ#0]THEN#550=1. (the ball's radius, unless the sweep gives it)
N30 G53 G0 Z0
N40 G43 H20 G0 X20. Y-20.
N50 G65 P9810 Z5. F3000.
N60 G65 P9811 Z0 Q5. S1 (the top face: G54 Z0 on the setup sheet)
N70 G65 P9810 Z50.
N80 G0 X0 Y0 (the bore: G54 X0 Y0 on the setup sheet)
N90 G65 P9810 Z-10.
N100 G65 P9814 D40. Q5. S1
N110 G65 P9810 Z50.
N120 M30
%
