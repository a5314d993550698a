(G66 modal call: the macro runs after each block that moves, with the)
(arguments of the G66 block; not for the macro's own moves; G67 cancels)
G21 G90 G54
G0 X0 Y0 Z0
G66 P7500 A2. Z-1. (no move here: Z is an argument)
G1 X10. F1000.
Y5.
#120=#4012 (66: modal call active)
G67
X20.
#121=#4012
M30
O7500
#100=#100+1 (calls)
#101=#101+#1
G91 G1 Z#26 F500. (this move does not call again)
G90
M99
