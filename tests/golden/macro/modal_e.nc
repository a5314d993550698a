(#4108: the last E word, modal information beside #4109 F: 0 before any,)
(set by a block with E alone or with a move, kept by a block without E)
G21 G90 G17 G94
#100=#4108
E1.5
#101=#4108
G1 X1. F100. E2.25
#102=#4108
G1 X2.
#103=#4108
M30
