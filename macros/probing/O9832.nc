%
O9832 (SKIPNC PROBING LIBRARY - PROBE ON)
(G65 P9832: switches the probe on. #555: the M code that switches it on,)
(vacant for a probe that is always on, a cabled one; #557: seconds to)
(wait after it, vacant for none. #554 = 1 while the probe is on.)
(Written for skipnc; see docs/probing-cycles.md.)
IF[#555EQ#0]GOTO20
M#555
IF[#557EQ#0]GOTO20
G04 X#557
N20#554=1
M99
%
