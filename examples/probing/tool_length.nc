%
O5006 (TOOL LENGTH ON THE TOOL SETTER, THEN G43 H1)
(T1 comes down on the setter fast, backs off 2 mm and comes down slowly;)
(its length goes to H1 with G10 L10, and G43 H1 brings its tip 5 mm over)
(the setter.)
(Results: #102 length, #11001 H1, after G43 H1 #103 = #5083, #104 = #5023.)
#110 = -300. (setter top, machine Z, from its calibration)
#111 = 0.002 (setter pre-travel)
G21 G90 G17 G40 G49 G54
G53 G0 Z0
T1 M06
G0 X-250. Y-150.
G0 Z-170.
G31 Z-190. F300. (fast)
G91 G0 Z2.
G90 G31 Z-190. F20. (slow)
#101 = #5063 (the gauge line's Z: G54 is zero and no length offset is on)
#102 = #101 - #110 + #111
G10 L10 P1 R#102
G91 G0 Z10.
G90 G43 H1 G0 Z-295.
#103 = #5083 (the active length offset: H1)
#104 = #5023 (the gauge line, machine Z: the tip 5 mm over the setter)
G49 G53 G0 Z0
T20 M06
M30
%
