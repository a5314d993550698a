( Units of stored values, LinuxCNC: a G38.2 under G20 on a metric machine )
( stores #5061-#5069 in the coordinate system and units of the program at )
( the probe [LinuxCNC "Parameters": "Coordinates are in the coordinate )
( system in which the G38 took place"; rs274ngc converts to program units )
( when it stores them]; a later G21 does not convert them. #5161-#5390 are )
( in machine units [tests/compat/linuxcnc/g92_g20_metric.nc]. By hand: the )
( surface at machine Z -12.7 is Z -0.5 in: #5063 = -0.5 [#100, #101 after )
( G21], #5070 = 1; to the thousandth of an inch: mill3 samples the probe )
( input each period, 4 micrometres past the surface at F10 in/min. )
G20 G90 G54
G38.2 Z-1 F10
#100 = #5063
#102 = #5070
G21
#101 = #5063
M2
