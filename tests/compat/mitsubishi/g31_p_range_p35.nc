%
O3003 (G31 P OUT OF RANGE: PROGRAM ERROR P35)
( Compatibility: in the style of the Mitsubishi manual's own warning example )
( for multi-step skip 2 [programming manual 15.4 [5], manualshive.com/en/ )
( manual/mitsubishi-electric/m700v-series/238523?page=567: "G31 P500. F100" )
( is taken as a skip signal parameter, and P35 follows], as a program that )
( meant P as an axis or a dwell would write it. )
( Constructs: G31 P within 1-255 [a mask], then G31 P500. [out of range]. )
( Expected by hand: G31 P1 X20. F200. with the probe in the air runs to X20 )
( [#100 = 20]; G31 P500. Z-10. F100. is program error P35 [SETTING VALUE )
( RANGE OVER] at line 16, before it moves: the machine stays at X20 Z0. )
G21 G90 G17 G40 G49 G80
G90 G54 G0 X0 Y0 Z0
G31 P1 X20. F200.
#100 = #5061
G31 P500. Z-10. F100.
M30
%
