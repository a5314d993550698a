%
O3001 (MULTI-STEP SKIP G31.1 FAST, G31.2 SLOW)
( Compatibility: in the style of the two-speed Z touch written for )
( Mitsubishi M700V/M800 controls with the multi-step skip function 1 )
( [programming manual 15.3 "Multi-step Skip Function; G31.n, G04", )
( manualshive.com/en/manual/mitsubishi-electric/m700v-series/238523?page=564: )
( G31.1/G31.2 with the feed and skip condition set by parameters #1175-#1180]. )
( Constructs: G31.1 and G31.2 without F [their feeds 1176/1178], G31.3 with )
( F, the F modal left unchanged by them, G65 with a local argument, )
( IF [..] GOTO, #3000 on a miss [not reached], #5063 with H20 in it. )
( Expected by hand [G54 = machine, H20 = 150, ball radius 1]: G31.1 Z-240 at )
( 600 mm/min touches the top -230 at ball centre -229: #5063 = -229 + 150 = )
( -79 [#101]; back 2, G31.2 Z-233 at 40 mm/min touches at -79 again [#102]; )
( the face #103 = -79 - 150 - 1 = -230. The G31.3 X120. F100. listens to )
( skip signals 2 and 3 [#1179 = 6]: the probe is on 1, so it runs to its )
( end point X120 [#104 = 120]. #105 = #4109 = 2000: the F of G1 before. )
( The feeds show in where each touch stops [immediate stop, 1 ms servo: one )
( period of travel past the touch]: G31.1 at 600 mm/min -229.010, G31.2 )
( at 40 mm/min -229.0007 [work Z of the ball centre]. )
G21 G90 G17 G40 G49 G80
G91 G28 Z0
G90 G54 G0 X0 Y0
G43 H20 Z-200.
G1 Z-210. F2000.
G65 P9301 Z-240.
#101 = #110
#102 = #111
#103 = #5063 - 150. - 1.
G0 Z-200.
G31.3 X120. F100.
#104 = #5061
#105 = #4109
G0 Z0
M30
O9301 (TWO-SPEED Z TOUCH: Z END)
IF [#26 EQ #0] GOTO 91
G90 G31.1 Z#26
#110 = #5063
IF [ABS[#5063 + 150. - #26] LT 0.001] GOTO 92
G91 G0 Z2.
G31.2 Z-4.
G90
#111 = #5063
M99
N91 #3000 = 91 (ARGUMENT MISSING)
N92 #3000 = 92 (PROBE DID NOT TOUCH)
M99
%
