%
O9833 (SKIPNC PROBING LIBRARY - PROBE OFF)
(G65 P9833: switches the probe off. #556: the M code that switches it off,)
(vacant for none. #554 = 0 while the probe is off.)
IF[#556EQ#0]GOTO10
M#556
N10#554=0
M99
%
