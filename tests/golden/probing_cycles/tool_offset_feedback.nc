%
O19 (T V F: THE ERRORS FED BACK TO THE WEAR OF TOOL OFFSETS)
(O9811 Z-0.4 T6 on the top face, G54 Z-0.37: the face is 0.03 high, the)
(tool that cut it 0.03 short in effect: H6 wear #10006 = -0.03. The same)
(with T7 V0.05: 0.03 is inside the dead band, #10007 stays 0.)
(O9812 X50.65 T8 on the 50.6 pocket: 0.05 of metal left across, 0.025 a)
(side: D8 wear #12008 = -0.025. O9814 D30.02 T5 F0.5 on the 30 mm boss:)
(0.02 too little metal across, 0.01 a side, half of it fed back: D5 wear)
(#12005 = +0.005. No S, so G54 stays.)
N10 G21 G90 G17 G40 G49 G80 G54
N20 #550=1.
N30 G53 G0 Z0
N40 G43 H20 G0 X20. Y-20.
N50 G65 P9810 Z5. F3000.
N60 G65 P9811 Z-0.4 Q5. T6
N70 G65 P9811 Z-0.4 Q5. T7 V0.05
N80 G65 P9810 Z50.
N90 G0 X65.05 Y-90.5
N100 G65 P9810 Z-10.
N110 G65 P9812 X50.65 Q5. T8
N120 G65 P9810 Z50.
N130 G0 X140.789 Y-70.821
N140 G65 P9810 Z25.
N150 G65 P9814 D30.02 Z10. Q5. R5. T5 F0.5
N160 G65 P9810 Z50.
N170 M30
%
