%
O5002 (WEB AND POCKET WIDTH)
(A web: touch both outer faces 10 mm below its top. A pocket: touch both)
(inner walls 10 mm below the plate's top. Both across X.)
(Results: #103 the web's width, #106 the pocket's width.)
#120 = 1.0 (effective ball radius, from calibration)
G21 G90 G17 G40 G54
G43 H20 G0 Z-200.
(Web: +X face, then -X face)
G0 X125. Y50.
G0 Z-219.87
G31 X90. F300.
#101 = #5061
G0 X125.
G0 Z-200.
G0 X88.
G0 Z-219.87
G31 X130. F300.
#102 = #5061
G0 X88.
G0 Z-200.
#103 = #101 - #102 - 2 * #120
(Pocket: +X wall, then -X wall)
G0 X-15. Y-60.
G0 Z-239.87
G31 X20. F300.
#104 = #5061
G0 X-15.
G31 X-50. F300.
#105 = #5061
G0 X-15.
G0 Z-200.
#106 = #104 - #105 + 2 * #120
G49 G53 G0 Z0
M30
%
