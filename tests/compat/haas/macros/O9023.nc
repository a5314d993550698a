%
O9023 (TOOL LENGTH ON THE TOOL SETTER - OWN MACRO FOR THE COMPATIBILITY)
(PROGRAMS. In the style of the call Haas posts write, G65 P9023 A12. T..)
(H.. D..; our own text. T: the tool, put in the spindle here; H: its)
(nominal length, from which the approach height is found. The setter's)
(centre and top, machine coordinates, are #560 #561 #562 [calibration)
(data]. One touch at F100 from 10 mm over the nominal tip; the length,)
(gauge line to the contact, goes to the tool's length offset #[2000+T])
(and its wear #[2200+T] is cleared [Haas numbering]. #145: the length.)
(The work system's Z offset must be 0: the G31's Z is the machine's.)
(No touch: alarm 92.)
IF [#20 EQ #0] GOTO 98
T#20 M06
G49 G53 G0 Z0
G53 G0 X#560 Y#561
G53 G0 Z[#562 + #11 + 10.]
G31 Z[#562 + #11 - 10.] F100.
IF [ABS[#5063 - [#562 + #11 - 10.]] LT 0.0005] GOTO 97
#145 = #5063 - #562
#[2000 + #20] = #145
#[2200 + #20] = 0
G53 G0 Z0
M99
N97 #3000 = 92 (PROBE OPEN - NO SURFACE FOUND)
N98 #3000 = 93 (FORMAT ERROR - NO TOOL T)
M99
%
