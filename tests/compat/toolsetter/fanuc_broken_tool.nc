%
O2002 (BROKEN TOOL CHECK ON THE TOOL SETTER)
( Compatibility: in the style of the Renishaw-type broken tool detection )
( macro called after a cutting tool [G65 P9853-like "T.. H.. tolerance" )
( call], the tool length range check of mmsonline.com/articles/t-codes- )
( simplify-tool-length-confirmation-process [H offsets read through system )
( variables, an alarm when out of range] and the #3000 traps of cncci.com. )
( Constructs: G65 with T and H arguments, G43 H#.. from an argument, G31 )
( onto the setter with the length offset on, #5063 less the setter's top, )
( #11000+H / #10000+H [memory C geometry and wear], ABS, IF .. GOTO, )
( #3000 = 88 with its message: alarm 3088. )
( Expected by hand [G54 = machine; setter top -300]: with G43 H2 [80] the )
( G31 aims the tip at -305, the gauge line at -225; the real tip [77.5] )
( meets the setter with the gauge line at -222.5: #5063 = -222.5 [Fanuc keeps )
( the offset in it], the length -222.5 - [-300] = 77.5 [#100], 2.5 short of )
( 80 > the tolerance 0.3: alarm 3088 TOOL BROKEN at line 37. )
G90 G17 G40 G49 G80 G21
G91 G28 Z0
G90 G54 G0 X-250. Y-150.
G65 P9862 T2. H0.3
M30
O9862 (BROKEN TOOL: T TOOL = OFFSET, H TOLERANCE)
IF [#20 EQ #0] GOTO 91
IF [#11 EQ #0] THEN #11 = 0.5
#30 = -300. (SETTER TOP, MACHINE Z)
G43 H#20 G0 Z[#30 + 10.]
G31 Z[#30 - 5.] F300.
IF [ABS[#5063 - [#30 - 5. + #[11000 + #20] + #[10000 + #20]]] LT 0.001] GOTO 92
#100 = #5063 - #30
#101 = #[11000 + #20] + #[10000 + #20]
G0 Z[#30 + 10.]
IF [ABS[#100 - #101] GT #11] GOTO 88
M99
N91 #3000 = 91 (ARGUMENT MISSING)
N92 #3000 = 92 (NO TOOL)
N88
#3000 = 88 (TOOL BROKEN)
M99
%
