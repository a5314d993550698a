%
O2001 (G37 AUTOMATIC TOOL LENGTH MEASUREMENT, WEAR UPDATE)
( Compatibility: in the style of the G37 tool-length examples of Fanuc-type )
( manuals and the Haas mill manual's G37 page [easymanua.ls/haas/vf-1/ )
( manual?p=169: "G43 H.. then G37 H.. Z.. F.."], written for a Fanuc 0i-M: )
( G43 H1 first, then G37 Z at the setter's top [no H in the G37 block]. )
( Constructs: a post's safe-start line, T1 M06, G43 H1, G37 Z [parameters )
( 6241 feed, 6251 gamma, 6254 epsilon at their defaults 100, 10, 1], ZAE )
( X4.2, #10001 [H1 wear] and #11001 [H1 geometry] reads, #5063, #4111. )
( Expected by hand: H1 = 100, the real tool 100.2. G37 Z-300. aims the tip )
( at the setter's top: the gauge line's measuring position is -300 + 100 = )
( -200; the tip touches with the gauge line at -300 + 100.2 = -199.8, 0.2 )
( before it [within epsilon 1]. The difference goes to H1's wear: #10001 = )
( 0.2, #11001 stays 100 [#102]; #5063 = -199.8 [the gauge line: Fanuc's )
( skip position keeps the length offset in it]. G0 Z-290. then puts the )
( tip 10 over the setter: the gauge line at -290 + 100.2 = -189.8. )
G90 G17 G40 G49 G80 G21
G91 G28 Z0
G90 G54 G0 X-250. Y-150.
T1 M06
G43 H1 Z-250.
G37 Z-300.
#101 = #10001
#102 = #11001
#103 = #5063
#104 = #4111
G0 Z-290.
M30
%
