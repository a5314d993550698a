( Units of stored values, Fanuc: the skip position #5061.. of a G31 under )
( G20 on a metric machine is in work coordinates and inches; it keeps the )
( number latched when the program goes back to G21, as the offsets keep )
( theirs [B-63944EN/02 8.2]. By hand: the surface at machine Z -12.7 mm is )
( Z -0.5 in with G54 zero: #5063 = -0.5 [#100], and still -0.5 under G21 )
( [#101]. )
G20 G90 G54
G31 Z-1. F10.
#100 = #5063
G21
#101 = #5063
M30
