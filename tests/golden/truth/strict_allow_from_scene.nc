(Strict mode people can use: the scene's [strict] allow names the warning a job)
(accepts, as --allow does on the command line. The probe's real length, 102.5 mm, is)
(not the 102.0 mm of H20: a warning, probe_length_differs, that this scene allows,)
(so --strict runs on to the end. #101 = -196.5 - 102.0 = -298.5 [as the golden)
(warnings/probe_length_differs works it out].)
G21 G90 G17 G40 G54
G43 H20 G00 Z-150.
G31 Z-320. F100
#101 = [#5063 - 102.0]
G00 Z-150.
M30
