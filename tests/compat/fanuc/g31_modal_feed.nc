%
O1011 (FANUC: A TOUCH WITH A MODAL FEED - THE SAME PROGRAM AS HAAS'S)
( Compatibility: in the style of the Fanuc-family single-surface touches )
( of examples/probing/surface.nc and of Fanuc Renishaw-style macros that )
( set the feed once and write G31 without F; the twin of tests/compat/ )
( haas/g31_modal_feed_refused.nc, which the haas dialect refuses. )
( Constructs: the safe-start line, G01 F300. setting the modal feed, G31 )
( without F [Fanuc: the modal F], #5063 less #5083. )
( Expected by hand: G54 Z = -225; the ball [H20 = 150 to its centre, )
( plate.scene.toml of the Haas suite] meets the plate's top -229.87 with )
( its centre at machine -228.87 = work -3.87: #100 = -3.87. )
G00 G17 G40 G49 G80 G90 G94 G97
G21
G10 L2 P1 X30. Y0. Z-225.
T20 M06
G54 G00 X0. Y0.
G43 H20 Z-3.
G01 F300.
G31 Z-10.
#100 = #5063 - #5083
M30
%
