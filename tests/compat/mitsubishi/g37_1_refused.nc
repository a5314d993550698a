%
O3004 (AUTOMATIC TOOL LENGTH MEASUREMENT G37.1: REFUSED BY NAME)
( Compatibility: in the style of the Mitsubishi M700V/M70V tool-length )
( measurement of programming manual 15.1 [manualshive.com/en/manual/ )
( mitsubishi-electric/m700v-series/238523?page=555: "G37.1 Z_ R_ D_ F_", )
( parameters #8004 SPEED, #8005 ZONE r, #8006 ZONE d]: T1 with G43 H1 over )
( the setter, then G37.1 toward the measuring position. )
( Constructs: G37.1 Z R D F. skipnc does not simulate it: the run stops at )
( the block with alarm not_simulated [SN9024] naming G37.1, before any )
( motion of that block; nothing runs past it. )
( Expected by hand: the tool stands at work Z-250 [G43 H1 = 100: gauge line )
( -150] when line 18 is refused; #100 = 1 [set before] and #101 vacant. )
G21 G90 G17 G40 G49 G80
G91 G28 Z0
G90 G54 G0 X-250. Y-150.
G43 H1 Z-250.
#100 = 1
G37.1 Z-300. R10. D2. F100.
#101 = #5063
M30
%
