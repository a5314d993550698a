( The probe's real length, 102.5 mm, is not the H20 the control believes, )
( 102.0 mm: the run is not refused, the values stored follow from both, and )
( one warning says so. By hand: the ball's lowest point meets the top at )
( machine Z -300 when the ball centre is at -299, so the gauge line is at )
( -299 + 102.5 = -196.5. This dialect's #5063 is the tool reference point )
( [the gauge line], #100 = -196.5; the program takes out the H it believes: )
( #101 = -196.5 - 102.0 = -298.5, the surface looks 1.5 mm high [0.5 mm from )
( H, 1 mm the ball radius: what a calibration cycle takes out]. )
G21 G90 G17 G40 G54
G43 H20 G00 Z-150.
G31 Z-320. F100
#100 = #5063
#101 = [#5063 - 102.0]
G00 Z-150.
M30
