%
O0300 (SKIPS THAT CAN ONLY MISS)
(The probe's ball is 10 mm over the plate. The first G31 goes up, away)
(from the plate, and can only run to its end point: warning. The second)
(goes across the plate without coming down: warning. The third goes)
(down and touches: no warning.)
G21 G90 G17 G54
G0 X0 Y0 Z-140.
G31 Z-100. F500.
G0 Z-140.
G31 X40. F500.
G0 X0
G31 Z-180. F500.
G0 Z-100.
M30
%
