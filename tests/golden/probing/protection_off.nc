(Probe protection off, parameter 90020 = 0: the G01 move runs the ball)
(into the clamp and on, until the stylus has been pushed past its 2 mm)
(of over-travel: alarm 9061 with the ball centre at X-9.)
G21 G90 G54
G43 H20 G0 Z-150.
G0 X-30. Y75.
G0 Z-215.
G1 X30. F500.
G0 Z-150.
M30
