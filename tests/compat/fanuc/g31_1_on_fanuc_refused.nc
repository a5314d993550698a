%
O1006 (A MITSUBISHI TWO-SPEED TOUCH LOADED ON A FANUC)
( Compatibility: the two-speed Z touch of mitsubishi/g31_1_two_step [in the )
( style of the M700V/M70V manual 15.3 multi-step skip G31.1/G31.2] moved to )
( a Fanuc 0i machining centre unchanged, as happens when a shop shares its )
( probing programs between controls. )
( Constructs: G31 on Fanuc, then G31.1: Fanuc's multi-step skip is G31 P1-P4, )
( and skipnc does not simulate a G31.1 there: the run stops at the block with )
( alarm not_simulated [SN9024] naming G31.1, before it moves; nothing runs )
( past it. )
( Expected by hand [G54 = machine, H20 = 150, ball radius 1, plate top )
( -230]: the plain G31 Z-240. touches at ball centre -229: #5063 = -79 )
( [#100]; after the back-off to work Z-227 the G31.1 of line 22 is refused. )
G90 G17 G40 G49 G80 G21
G91 G28 Z0
G90 G54 G0 X0 Y0
G43 H20 Z-200.
G31 Z-240. F300.
#100 = #5063
G91 G0 Z2.
G90
G31.1 Z-240. F40.
#101 = #5063
M30
%
