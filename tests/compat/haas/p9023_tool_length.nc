%
O1009 (HAAS: TOOL LENGTH ON THE SETTER - G65 P9023 A12. T1 H.. D..)
( Compatibility: in the style of the tool measurement Autodesk's "HAAS - )
( Next Generation Control" post writes before a tool is used [ThomasLeMezo )
( /enstabretagne-inventor-cam, postpro/haas_vf2_inspect_surface_ENSTA.cps, )
( writeToolMeasureBlock: G65 P9023 A<type>. T<n> H<body length> D<dia>]. )
( Constructs: G65 P9023 with A T H D; our O9023 [T M06, G49, G53 moves, )
( one G31 with F, #[2000 + T] and #[2200 + T] written as Haas numbers )
( them: #2001 length, #2201 length wear]; G43 H1 afterwards reads the )
( length the macro wrote [#5083]. )
( Expected by hand: the setter's top is machine Z-300 [plate.scene.toml, )
( #562]; T1 is 123.456 long [scene], though H1 says 120 [haas_vf.toml]. )
( The tip meets the top with the gauge line at -300 + 123.456 = -176.544: )
( #145 = #2001 = 123.456 [to 1e-5 mm: the latch comes 1 nm short], the )
( same offset read by its long number #11001, )
( #2201 = 0, and after G43 H1 #5083 = 123.456. G54 is zero. )
G00 G17 G40 G49 G80 G90 G94 G97
G21
#560 = -250. (setter centre X, machine)
#561 = -150. (setter centre Y)
#562 = -300. (setter top Z)
G65 P9023 A12. T1 H120. D10.
#110 = #2001
#111 = #11001
#112 = #2201
G43 H1
#113 = #5083
G49
M30
%
