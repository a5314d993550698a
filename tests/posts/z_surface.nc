%
O2003 (PROBING-Z)
(Written for skipnc in the output format of the Autodesk Fusion generic)
(Fanuc post [fanuc.cps, its probing case for this operation], run)
(unmodified with -I macros/probing; probe.vars is the control memory:)
(#550 = 1 [the ball calibrated]. The part [part.scene.toml] sits off)
(its CAD place by X-0.123 Y-0.044 Z-0.37 in G54 X-80 Y30.5 Z-229.5,)
(the CAD features below are the true ones + [0.123, 0.044, 0.37]:)
(top face: CAD Z0, true Z-0.37, at X20. Y-20.; the protected move to)
(Z0 + 5 clearance. #137 = -0.37, #142 = -0.37; S1.: #5223 = -229.87.)
(The retract G65 P9810 Z50. has no F [the post leaves it out]: O9810)
(takes the last F, kept in #551: 1000 [memory_after].)
N10 G90 G94 G17 G49 G40 G80
N15 G21
N20 G53 G0 Z0.
N25 T20 M6
N30 G54 G0 X20. Y-20.
N35 G43 Z50. H20
N40 G65 P9832
N45 G65 P9810 Z5. F1000.
N50 G65 P9811 Z0. Q5. S1.
N55 G65 P9810 Z50.
N60 G65 P9833
N65 G53 G0 Z0.
N70 M30
%
