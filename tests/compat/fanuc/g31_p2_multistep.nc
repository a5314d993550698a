%
O1004 (MULTI-STEP SKIP: THE PROBE ON SKIP2, G31 P2)
( Compatibility: in the style of the Fanuc-compatible probing macros for )
( machines whose spindle probe is wired to a second skip input [G31 P2 in )
( the Renishaw-type macros' "skip select" setting, Fanuc 0i multi-step skip )
( G31 P1-P4, cnc.wiki/en/g31-skip-function-and-probe-usage], with a fast )
( touch, a back-off and a slow touch, then a side touch in X-. )
( Constructs: G31 P2 Z / X [multi-step skip: SKIP2 = X0.1], G91/G90 in one )
( cycle, a missed plain G31 [it listens to X0.4 only] that runs to its end )
( point [K omitted: no alarm, 90001 = 0; skipnc warns skip_missed_read at )
( the read of #5063 after it], #5061/#5063. )
( Expected by hand [G54 = machine, H20 = 150, ball radius 1]: the plain G31 )
( Z-228 stops short of the plate [-229 would touch]: not triggered, #5063 = )
( -228 + 150 = -78 [#100]. G31 P2 fast then slow touch the top -230 at ball )
( centre -229: #5063 = -79 both [#101, #102]. Lifted to Z-225, moved to )
( X90 and down to Z-240, G31 P2 X70. touches the face X80 at ball centre )
( X81: #5061 = 81 [#103]; the face #104 = 81 - 1 = 80. )
G90 G17 G40 G49 G80 G21
G91 G28 Z0
G90 G54 G0 X0 Y0
G43 H20 Z-200.
G31 Z-228. F500.
#100 = #5063
G31 P2 Z-240. F500.
#101 = #5063
G91 G0 Z2.
G90 G31 P2 Z-240. F50.
#102 = #5063
G0 Z-225.
X90.
G1 Z-240. F2000.
G31 P2 X70. F100.
#103 = #5061
#104 = #5061 - 1.0
G0 X90.
G0 Z0
M30
%
