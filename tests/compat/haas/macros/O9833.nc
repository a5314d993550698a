%
O9833 (PROBE OFF - OWN MACRO FOR THE COMPATIBILITY PROGRAMS)
(In the style of the call Haas posts write after probing, G65 P9833.)
#150 = 0
M99
%
