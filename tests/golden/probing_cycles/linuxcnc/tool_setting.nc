(The LinuxCNC tool-setting subroutines of macros/probing/linuxcnc on the)
(contact setter of tool_setting.scene.toml: a 12 mm disc at machine)
(X-250 Y-150, its top at Z-300, switching 2 um pressed: #<_setter_z> =)
(-300.002, #<_setter_radius> = 6 - 0.002 = 5.998. T1 is 123.456 long, 10)
(across; its tool table says 120.05 long, 9.8 across.)
(1. o<tool_length> [0] [5]: the gauge line switches at -300.002 +)
(123.456: #100 = 123.456, #101 = 123.456 - 120.05 = 3.406, and the table)
(length becomes 123.456, on again with G43: #102 = #5403 = 123.456.)
(2. o<tool_broken> [0.1]: T1 is where expected: #103 = 0.)
(3. o<tool_diameter> [0] [5]: the tool's axis switches at X-250 +/-)
([6 + 5 - 0.002]: #104 = 2 x 10.998 - 2 x 5.998 = 10, #105 = 10 - 9.8 =)
(0.2, #106 = 0 [the tool on the setter's axis]; the table's diameter)
(becomes 10: #107 = #5410 = 10. 4. Again with tol 0.01: #108 = 0.)
(5. T2, 80 long [its table 100], o<tool_broken> [0.5]: no touch by 0.5)
(past 100: the run ends with BROKEN TOOL, the table left 100.)
(LinuxCNC samples the probe input once a servo period, 1 ms: a touch at)
(the slow 100 mm/min reads up to 0.00167 mm past the switch, a diameter)
(from two up to twice that; the broken-tool check's fast 1000 mm/min)
(touch up to 0.0167: checked within 0.004, #103 within 0.017.)
G21 G90 G17 G40 G49 G80 G54
#<_setter_x> = -250
#<_setter_y> = -150
#<_setter_z> = -300.002
#<_setter_radius> = 5.998
G10 L1 P1 Z120.05 R4.9
G10 L1 P2 Z100 R4
G53 G0 Z0
T1 M6
G43
o<tool_length> call [0] [5]
#100 = #<_tool_length>
#101 = #<_tool_error>
#102 = #5403
o<tool_broken> call [0.1]
#103 = #<_tool_error>
o<tool_diameter> call [0] [5]
#104 = #<_tool_diameter>
#105 = #<_tool_error>
#106 = #<_tool_centre>
#107 = #5410
o<tool_diameter> call [0.01] [5]
#108 = #<_tool_error>
G53 G0 Z0
T2 M6
G43
o<tool_broken> call [0.5]
M2
