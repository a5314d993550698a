(Two plunges of T2 into the stock, each followed by a G00 retract out of)
(the hole it cut. The servo of mill3_lowgain lags its command, kp 30/s without)
(feedforward: 0.17 mm at F300. The first retract starts as soon as the G01's)
(command ends: the tool goes on down, cutting, while the rapid takes up)
(its lag, then turns back 0.128 mm short of Z-3, without a collision.)
(The second plunge dwells first, so its hole is Z-3 deep. The probe then)
(touches both bottoms: #100 = -2.87224133, #101 = -3. An integration of)
(the servo's equation, dz/dt = 30 [command - z], gives -2.8723 for #100.)
G21 G90 G17 G40 G49 G54
G53 G0 Z0
T2 M06
S3000 M03
G43 H2 G0 Z5.
G0 X20. Y20.
G1 Z-3. F300.
G0 Z5.
G0 X40.
G1 Z-3.
G4 P500
G0 Z5.
M05
G49 G53 G0 Z0
T20 M06
G43 H20 G0 Z5.
G0 X20. Y20.
G31 Z-10. F300.
#100 = #5063 - #5083 - 1.0
G0 Z5.
G0 X40.
G31 Z-10. F300.
#101 = #5063 - #5083 - 1.0
G0 Z5.
G49 G53 G0 Z0
M30
