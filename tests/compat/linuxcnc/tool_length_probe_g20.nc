( Compatibility: in the style of LinuxCNC/linuxcnc nc_files/tool-length-probe.ngc - )
( an inch program measuring tool lengths on a switch under the G30 position, )
( run here on a METRIC machine [mill3, mm]. )
( Constructs: G30 recalled under G20, G38.2 in inches, G91 G0 Z.2 off the )
( switch, #1000 = #5063, G49, G43.1 Z[#5063-#1000], [print, ...]. )
( Expected by hand: G30.1 [under G21] stores the switch position X-250 Y-150 )
( Z-90 in #5181.. in the machine's unit, mm [LinuxCNC keeps #5161-#5390 in )
( machine units]. Under G20, G30 goes back there: machine X-250 Y-150 Z-90 mm )
( [not 25.4 times as far]. The switch closes at machine Z -100 mm; G54 is zero )
( and no length applies, so #5063 = -100 / 25.4 = -3.937008 inch, for the )
( reference tool and again for the second; the new length #5063-#1000 = 0, )
( so #5403 [the Z length] reads 0. Each latch is within the 6.4 um the axis )
( moves in one servo period at F15 inch/min; the machine ends 0.2 inch above )
( where it stopped, at X-250 Y-150 mm. )
G21 G90 G49
G53 G0 Z-90
G53 G0 X-250 Y-150
G30.1
G0 X0 Y0
G20 G90
G49
G30
G38.2 Z-5 F15
G91 G0 Z.2
#1000 = #5063
(print, reference length is #1000)
G90
G30
G49
G38.2 Z-5 F15
G91 G0 Z.2
G43.1 Z[#5063-#1000]
(print, new length is #5063)
G90
#1001 = #5403
M2
