%
O53 (O9853 TOOL LENGTH AND O9852 BROKEN TOOL CHECK ON THE TOOL SETTER)
(The setter switches when the tip is 2 um below its top, machine Z-300:)
(#560 = -300.002, its centre #561 = -250, #562 = -150. T1 is 123.456)
(long, its offset H1 set to 120 + wear 0.05: O9853 T1 reads the gauge)
(line at the switch, -300.002 + 123.456 = -176.546, so #137 = -176.546 -)
(-300.002 = 123.456, #102 = #142 = 123.456 - 120.05 = 3.406; #11001 =)
(123.456, wear #10001 = 0. O9852 T1 H0.1 then finds it where expected:)
(#101 = #142 = 0. T2 is 80 long, broken, its H2 100: O9852 T2 H0.5 goes)
(down to 0.5 short of 100 without a touch: 3093 BROKEN TOOL, H2 left 100.)
N10 G21 G90 G17 G40 G49 G80 G54
N20 #560=-300.002
N30 #561=-250.
N40 #562=-150.
N50 G10 L10 P1 R120.
N60 G10 L11 P1 R0.05
N70 G10 L10 P2 R100.
N80 G53 G0 Z0
N90 T1 M6
N100 G65 P9853 T1.
N110 #100=#137
N115 #102=#142
N120 G65 P9852 T1. H0.1
N130 #101=#142
N140 G53 G0 Z0
N150 T2 M6
N160 G65 P9852 T2. H0.5
N170 M30
%
