%
O4001 (TOOL LENGTH ON THE SETTER, MITSUBISHI, SKIP SIGNAL 2)
( Compatibility: in the style of the tool-setter programs for Mitsubishi )
( M70/M80/M800 machining centres whose setter is wired to a second skip )
( signal [G31 P2 F.., programming manual 15.4, manualshive.com/en/manual/ )
( mitsubishi-electric/m700v-series/238523?page=566] with the length written )
( by G10 L10 and its wear cleared by G10 L11, as tool-setter makers' )
( Mitsubishi macros do. )
( Constructs: G31 P2 fast and slow [the bit of signal 2], the F modal not )
( changed by a G31 F [#4109], G49 then G31 on the gauge line, G10 L10 P1 R, )
( G10 L11 P1 R0, IF [..] GOTO, #3000 on a miss [not reached], G43 H1 after. )
( Expected by hand [G54 = machine, setter top -300]: T1 [99.95] switches the )
( setter with the gauge line at -300 + 99.95 = -200.05: #5063 = -200.05 both )
( times; the length #100 = -200.05 + 300 = 99.95 into H1 [#11001], wear 0; )
( #101 = #4109 = 3000, the F of the G1 before the G31 blocks. G43 H1 )
( Z-290. puts the gauge line at -290 + 99.95 = -190.05. )
G21 G90 G17 G40 G49 G80
G91 G28 Z0
G90 G54 G0 X-250. Y-150.
G1 Z-150. F3000.
G31 P2 Z-230. F400.
IF [ABS[#5063 + 230.] LT 0.001] GOTO 92
G91 G0 Z2.
G90 G31 P2 Z-230. F25.
#100 = #5063 + 300.
#101 = #4109
G10 L10 P1 R#100
G10 L11 P1 R0
G0 Z-150.
G43 H1 Z-290.
M30
N92 #3000 = 92 (NO TOUCH ON THE SETTER)
M30
%
