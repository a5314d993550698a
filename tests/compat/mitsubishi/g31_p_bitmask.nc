%
O3002 (MULTI-STEP SKIP 2: G31 P AS A MASK OF SKIP SIGNALS)
( Compatibility: in the style of the side touch of Mitsubishi M70/M800 )
( probing programs that pick the probe's input with G31 P [programming )
( manual 15.4 "Multi-step Skip Function 2; G31", manualshive.com/en/manual/ )
( mitsubishi-electric/m700v-series/238523?page=566 and ?page=567: "G31 X100. )
( P5 F100" skips on signal 1 or 3]. )
( Constructs: G31 P2 [signal 2 only] in free air, G31 P6 [2 or 3] onto the )
( face, the signal that ended it in the report [X0.2], #5061, WHILE .. DO1 )
( / END1 repeating the touch, averaging. )
( Expected by hand [G54 = machine, ball radius 1]: G31 P2 X85. meets nothing )
( and ends at X85 [#100]. Each of the three G31 P6 X70. from X90 touches the )
( face X80 at ball centre X81 on signal 3 [X0.2]: #5061 = 81; the mean face )
( #101 = 81 - 1 = 80; #102 = 3 touches. )
G21 G90 G17 G40 G49 G80
G91 G28 Z0
G90 G54 G0 X90. Y0
G43 H20 Z-240.
G31 P2 X85. F500.
#100 = #5061
#102 = 0
#103 = 0
WHILE [#102 LT 3] DO1
G0 X90.
G31 P6 X70. F100.
#103 = #103 + #5061
#102 = #102 + 1
END1
#101 = #103 / #102 - 1.
G0 X90.
G0 Z0
M30
%
