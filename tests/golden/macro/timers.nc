(#3001 millisecond timer from simulated time; a read of #3001 or of a)
(position waits for the motion before it to end [buffer stop])
G21 G90 G54
G0 X0 Y0 Z0
#3001=0
G4 P1500
#100=#3001
G1 X100. F6000.
#101=#5021
#102=#5041
#3001=0
#103=#3001
M30
