%
O2003 (SET THE LENGTHS OF T1-T3 ON THE TOOL SETTER)
( Compatibility: in the style of the "measure every tool of the job" )
( programs that Fanuc CAM posts and setter makers' macros write [a WHILE )
( over the tools, T M06, a fast and a slow G31 on the setter, G10 L10 for the )
( geometry and G10 L11 R0 to clear the wear], as in the tool-setter macros )
( shared on cnczone/practicalmachinist and the Renishaw-type O9853 calls. )
( Constructs: WHILE [..] DO1 / END1 with T#1 M06 inside, G49 before the )
( touch, G31 fast then slow, #5063 without a length offset, G10 L10 P R and )
( G10 L11 P R0, reads of #2201-#2203 [H geometry, the short form of a )
( machine with at most 200 offsets] and #11001-#11003, G43 H#.. after. )
( Expected by hand [G54 = machine, setter top -300, pre-travel 0.002]: each )
( tool switches the setter with its tip at -300.002; the gauge line is then )
( at -300.002 + L, #5063 = that, and the length set is #5063 - [-300] + 0.002 )
( = L: 100.05, 79.9, 60.0 into H1-H3 [#2201-#2203 = #11001-#11003], their )
( wear 0 [#10001-#10003]. G43 H3 Z-290. leaves T3's tip 10 over the setter: )
( the gauge line at -290 + 60 = -230. )
G90 G17 G40 G49 G80 G21
G91 G28 Z0
G90 G54 G0 X-250. Y-150.
#1 = 1
WHILE [#1 LE 3] DO1
G49 G0 Z-150.
T#1 M06
G31 Z-245. F500.
G91 G0 Z2.
G90 G31 Z-245. F30.
#2 = #5063 + 300. + 0.002 (THE LENGTH: SETTER TOP -300, PRE-TRAVEL 0.002)
G10 L10 P#1 R#2
G10 L11 P#1 R0
G0 Z-150.
#1 = #1 + 1
END1
#101 = #2201
#102 = #2202
#103 = #2203
G43 H3 G0 Z-290.
M30
%
