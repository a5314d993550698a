(A feed held for ever: the scene sets the feed override to 0 % at 0.1 s and never)
(releases it; the run ends one second later with SN9065 naming the override, within)
(a fraction of a second of wall time, not at limits.max_time_s)
G21 G90 G54
G1 X100. F1000.
M30
