%
O02025 (OUTER CORNER, THEN PROBING-Z WITH X LEFT OUT)
(Written for skipnc in the output format of the Autodesk Fusion "HAAS -)
(Next Generation Control" post [its probing case for this operation;)
(haas_vf2_inspect_surface_ENSTA.cps of ThomasLeMezo/enstabretagne-)
(inventor-cam], the Fanuc-post program ../modal_x_after_corner.nc in the Haas framing,)
(run unmodified in the haas dialect with -I macros/probing; probe.vars is the control memory:)
(#550 = 1 [the ball calibrated]. The part [part.scene.toml] sits off)
(its CAD place by X-0.123 Y-0.044 Z-0.37 in G54 X-80 Y30.5 Z-229.5,)
(the CAD features below are the true ones + [0.123, 0.044, 0.37]:)
(Edge case of the post: X and Y are modal words, and the corner call)
(writes X-69.877 Y-130.456, so the post takes X-69.877 as the current X)
(and leaves X out of the next operation's positioning when its X is the)
(same. The cycle returns the probe to where it started, X-75.877: the)
(machine is not where the post believes. Corner: S1. sets G54 X-80.123)
(Y30.456 as in outer_corner; the probe then stands at machine)
(X-80 - 75.877 = -155.877, off the plate, G54 X-75.754. The Z touch)
(to the CAD top Z0. with Q5. meets nothing by Z-5.: alarm 3087 PROBE)
(FAIL, and G54 Z, which S1. would have set, stays -229.5. The kept)
(#554 stays 1: the probe was on when the program stopped. The Haas)
(post switches the probe off at each operation's end and on at the next)
(one's start [onSectionEnd, onSection]: O9833, O9832 between the two.)
N10 G90 G94 G17
N15 G21
N20 G53 G0 Z0.
N25 G53 G0 X0. Y0.
N30 T20 M6
N35 G54
N40 G0 X-75.877 Y-136.456
N45 G43 Z50. H20
N50 G65 P9832
N55 G65 P9810 Z-5. F1000.
N60 G65 P9816 X-69.877 Y-130.456 Q5. S1.
N65 G65 P9810 Z50.
N70 G65 P9833
N75 G0 Y-120.
N80 G65 P9832
N85 G65 P9810 Z5.
N90 G65 P9811 Z0. Q5. S1.
N95 G65 P9810 Z50.
N100 G65 P9833
N105 G53 G0 Z0.
N110 G53 G0 X0. Y0.
N115 M30
%
