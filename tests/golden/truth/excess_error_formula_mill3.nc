(The excess-following-error limit of docs/skip-dialects.md, mill3: a torque limit skip)
(with no limit commanded [6280 = 0, no Q] pushes Z against a stop at Z-3 while its)
(command runs on at F300 [5 mm/s]. The alarm comes once the error passes)
(1.5 x rapid / kp + 1 mm = 1.5 x 500 / 50 + 1 = 16 mm: the command is then at)
(Z-19, 3.8 s after the block began. The axis stays at the stop, Z-3.)
G21 G90 G54 G0 X0 Y0 Z0
G31 P99 Z-60. F300.
M30
