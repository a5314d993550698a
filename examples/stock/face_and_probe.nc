%
O5030 (FACE THE STOCK 0.2 MM DEEP, THEN PROBE THE FACED TOP)
(Scene stock.scene.toml, machine stock.machine.toml: the stock is 60 x 40)
(mm in G54 with its top at Z0. T2, 10 mm across, faces it in five passes)
(along X at Z-0.2, 8 mm apart from Y4 to Y36, each starting and ending)
(clear of the stock; then the probe T20 touches the faced top at its)
(centre. With G43 H20 a work Z is the ball centre's.)
(Results: #100 the faced top's Z, -0.2; the report's stock removed volume)
(60 x 40 x 0.2 = 480 mm^3.)
#120 = 1.0 (effective ball radius, from calibration)
G21 G90 G17 G40 G49 G54
G53 G0 Z0
T2 M06
S3000 M03
G43 H2 G0 Z20.
G0 X-10. Y4.
G0 Z-0.2
G1 X70. F1200.
G0 Y12.
G1 X-10.
G0 Y20.
G1 X70.
G0 Y28.
G1 X-10.
G0 Y36.
G1 X70.
G0 Z20.
M05
G49 G53 G0 Z0
T20 M06
G43 H20 G0 Z20.
G0 X30. Y20.
G31 Z-10. F300.
#100 = #5063 - #5083 - #120 (#5063 has H20 in it)
G0 Z20.
G49 G53 G0 Z0
M30
%
