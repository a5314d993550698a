%
O1001 (BORE AND TOP FACE, IN THE STYLE OF A POSTED PROBING PROGRAM)
(Written for skipnc in the form the Autodesk Fusion generic Fanuc post)
(gives its probing operations: protected moves O9810 around each cycle,)
(the cycle with its nominal size, overtravel and S, the retract O9810 Z)
(without F. Run it with -I macros/probing on cycles.machine.toml with)
(part.scene.toml: the bore's centre, G54 X-0.123 Y-0.044 as set up, and)
(its top face, Z-0.37, are written into G54: #5221 = -80.123, #5222 =)
(30.456, #5223 = -229.87; #138 = 40.)
N10 G90 G94 G17 G49 G40 G80
N15 G21
N20 #550=1.
N25 G53 G0 Z0.
N30 T20 M06
N35 G54 G0 X0. Y0.
N40 G43 Z50. H20
N45 G65 P9832
N50 G65 P9810 Z-10. F1000.
N55 G65 P9814 D40. Q5. S1
N60 G65 P9810 Z50.
N65 G0 X20. Y-20.
N70 G65 P9810 Z5. F1000.
N75 G65 P9811 Z0. Q5. S1
N80 G65 P9810 Z50.
N85 G65 P9833
N90 G53 G0 Z0.
N95 M30
%
