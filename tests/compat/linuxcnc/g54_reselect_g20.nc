( Compatibility: in the style of LinuxCNC/linuxcnc nc_files/tool-length-probe.ngc )
( and of post-processor preambles that re-select the work system after G20: )
( work offsets stored metric, re-selected under G20, on a metric machine. )
( Constructs: G10 L2 P1 under G21, G20, G55 then G54 [LinuxCNC loads the )
( system from #5221.. when another one is selected], #5221 read under G20. )
( Expected by hand: G10 L2 P1 X10 Y5 stores #5221 = 10, #5222 = 5 [mm, the )
( machine's unit; LinuxCNC's rs274 stores G21 G10 L2 P1 X25.4 as 1.000000 on )
( its inch machine]. Re-selected under G20, G54 is still 10 mm, 5 mm: G0 X0 Y0 )
( goes to machine X 10, Y 5 mm [not 254, 127], and #5221 still reads 10. )
G21 G90 G54
G10 L2 P1 X10 Y5
G20
G55
G54
G0 X0 Y0
#100 = #5221
M2
