%
O54 (O9853 B1 AND B2: TOOL DIAMETER ON THE CONTACT TOOL SETTER)
(The setter of tool_setting: a 12 mm disc at machine X-250 Y-150, top)
(Z-300, switching 2 um pressed: #560 = -300.002, #566 = 6 - 0.002 =)
(5.998. T1 is 123.456 long and 10 across [radius 5.0]; its H1 is 120 +)
(0.05 wear, its D1 4.9 + 0.05 wear. G54 is X12.5 Y-7 Z-20 off the)
(machine, which the cycle takes out of its X and Z touches.)
(B2: the length as O9853 B0, #137 = 123.456, #142 = 3.406; then the tip)
(goes 2 below -300.002 and the side touches switch with the tool's axis)
(at machine X -250 + [5.998 + 5] = -239.002 and -260.998: #138 =)
(-239.002 - -260.998 - 2 * 5.998 = 10, #143 = 10 - 2 * 4.95 = 0.1,)
(#135 = 0 [on the setter's axis]; D1 = 5 [#105], its wear 0, H1 = 123.456.)
(B1 D3 H0.05 with D3 = 5.02 [expected 10.04]: a check, #143 = -0.04,)
(D3 left 5.02. B1 H0.1 with D1 set to 5.1 [expected 10.2]: #143 = -0.2,)
(more than 0.1 off: 3088 OUT OF TOLERANCE, D1 left 5.1.)
N10 G21 G90 G17 G40 G49 G80 G54
N20 #560=-300.002
N30 #561=-250.
N40 #562=-150.
N50 #566=5.998
N60 G10 L2 P1 X12.5 Y-7. Z-20.
N70 G10 L10 P1 R120.
N80 G10 L11 P1 R0.05
N90 G10 L12 P1 R4.9
N100 G10 L13 P1 R0.05
N110 G10 L12 P3 R5.02
N120 G53 G0 Z0
N130 T1 M6
N140 G65 P9853 T1. B2.
N150 #100=#138
N160 #101=#143
N170 #102=#135
N180 #103=#137
N185 #105=#13001
N190 G65 P9853 T1. B1. D3. H0.05
N200 #104=#143
N210 G10 L12 P1 R5.1
N220 G65 P9853 T1. B1. H0.1
N230 M30
%
