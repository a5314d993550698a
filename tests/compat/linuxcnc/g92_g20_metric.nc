( Compatibility: in the style of LinuxCNC/linuxcnc nc_files/tool-length-probe.ngc )
( and of programs that switch G20/G21 around a G92: the G92 offset kept in )
( #5211.. in the machine's unit on a metric machine. )
( Constructs: G92 under G21, #5211 read under G20, G92.2 then G92.3 under G20. )
( Expected by hand: at machine X 10 mm, G92 X0 makes the G92 offset 10 mm: )
( #5211 = 10 [mm, the machine's unit] read under G20 too [#100 = 10]. G92.2 )
( turns G92 off, keeping #5211; G92.3 under G20 applies it again as 10 mm, )
( so G0 X0 [inch] goes to machine X 10 mm, and G0 X1 to 10 + 25.4 = 35.4 mm. )
G21 G90 G54
G0 X10
G92 X0
G20
#100 = #5211
G92.2
G92.3
G0 X0
#101 = #<_abs_x>
G0 X1
M2
