( grbl on its own machine, the built-in grbl3: steppers, the position is the )
( step count. The switch closes at machine Z -20.5; at F100 the axis moves )
( 1.7 um per 1 ms period, so [PRB:] reads -20.500 to grbl's 3 decimals and )
( the run has no grbl_servo_lag warning. )
G21 G90
G53 G0 X-100 Y-100 Z-5
G38.2 Z-50 F100
G0 Z-5
M2
