%
O1011 (HAAS: A FANUC-STYLE TOUCH WITH A MODAL FEED IS REFUSED ON HAAS)
( Compatibility: in the style of the Fanuc-family single-surface touches )
( of examples/probing/surface.nc and of Fanuc Renishaw-style macros that )
( set the feed once [G01 F..] and then write G31 without F. The Haas )
( mill operator's manual, "G31 Feed Until Skip": "The G31 line must have )
( a Feed command." The same program runs on the fanuc dialect )
( [tests/compat/fanuc/g31_modal_feed.nc]. )
( Constructs: the safe-start line, G01 F300. setting the modal feed, G31 )
( without F. )
( Expected by hand: the haas dialect refuses the G31 block at line 21: )
( alarm skip_no_feed [9031, "G31 without a feed"], before the probe moves: )
( the machine rests where the G00 left it, work Z-3 = machine -228 + 150. )
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
