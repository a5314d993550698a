(Strict mode people can use: --strict --allow no_effect accepts the named warning:)
(G08, accepted without effect, stays a warning in the report and the run completes)
G21 G90 G54
G08 P1
G0 X10. Y0 Z0
M30
