(NCT: P selects skip inputs 1-4 as P0-P3; P4 is a syntax error 3051)
G21 G90 G54 G31 Z-10. F100. P4
M30
