%
O02008 (PROBING-X-CHANNEL-WITH-ISLAND)
(Written for skipnc in the output format of the Autodesk Fusion "HAAS -)
(Next Generation Control" post [its probing case for this operation;)
(haas_vf2_inspect_surface_ENSTA.cps of ThomasLeMezo/enstabretagne-)
(inventor-cam], the Fanuc-post program ../x_channel_island.nc in the Haas framing,)
(run unmodified in the haas dialect with -I macros/probing; probe.vars is the control memory:)
(#550 = 1 [the ball calibrated]. The part [part.scene.toml] sits off)
(its CAD place by X-0.123 Y-0.044 Z-0.37 in G54 X-80 Y30.5 Z-229.5,)
(the CAD features below are the true ones + [0.123, 0.044, 0.37]:)
(islands.scene.toml adds a 10 mm square island, top true Z-5.5, in)
(the pocket and a 12 mm pin, top Z-5.5, in the bore, both centred.)
(From Z-2. over the island, R-5.: out to 50.6/2 - 5 from the centre,)
(down to Z-10., touched outwards: #135 = 65.05, #138 = 50.6; S1.:)
(#5221 = -80.123.)
N10 G90 G94 G17
N15 G21
N20 G53 G0 Z0.
N25 G53 G0 X0. Y0.
N30 T20 M6
N35 G54
N40 G0 X65.173 Y-90.456
N45 G43 Z50. H20
N50 G65 P9832
N55 G65 P9810 Z-2. F1000.
N60 G65 P9812 X50.6 Z-10. Q5. R-5. S1.
N65 G65 P9810 Z50.
N70 G65 P9833
N75 G53 G0 Z0.
N80 G53 G0 X0. Y0.
N85 M30
%
