(A skip cut short by an alarm before any signal: the G31 goes down beside the clamp,)
(the probe's body lands on the clamp's top before the stylus touches anything: alarm)
(9062 with nothing latched, so the skip's time, position and machine position are null)
G21 G90 G54
G43 H20 G0 Z-150.
G0 X-13. Y75.
G31 Z-220. F1000.
G0 Z-150.
M30
