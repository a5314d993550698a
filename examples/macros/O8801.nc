%
O8801 (TOOL LENGTH ON A TOOL SETTER)
(G65 P8801 T..  with the tool above the setter, G54-G59 active.)
(T: offset number to set. #501: machine Z of the setter's contact face.)
(The length is from the spindle gauge line, machine Z0, to the tool tip.)
(It goes to the H geometry offset T, whose wear is set to 0.)
(The setter is input SKIP2, G31 P2. Result: #139 length.)
IF[#20EQ#0]THEN#3000=92(T MISSING)
IF[#501EQ#0]THEN#3000=95(SETTER NOT SET)
G49 (no length offset while measuring)
#10=#5003 (start)
G91 G31 P2 Z-300. F1000. (fast)
IF[ABS[#5063-[#10-300.]]LT0.001]GOTO93
G0 Z2.
#11=#5003
G31 P2 Z-4. F50. (slow: the measurement)
IF[ABS[#5063-[#11-4.]]LT0.001]GOTO93
G90 G0 Z#10
(machine Z of the touch: work Z plus EXT and the active G54-G59 offset)
#12=#5063+#5203+#[5203+ROUND[#4014-53]*20]
#139=#12-#501
#[11000+#20]=#139
#[10000+#20]=0
M99
N93#3000=93(NO SETTER CONTACT)
%
