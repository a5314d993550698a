(One value, one number: a touch between two increments. Fanuc-class controls)
(store #5061.. in whole least input increments, and the report's skips[].position)
(is that very number: -1.573, not -1.5728059)
G21 G90 G54
G0 X0 Y0 Z0
G31 Z-10. F100.
#100 = #5063
M30
