(G42, D2 = 5: an outer corner under 90 degrees at X20 Y0 goes round by the two vectors extended by the radius: the first side runs on to X25 Y-5, a line joins X26.708204 Y2.236068 - 5 back along the second side from its offset point -, then the second side; the G40 block of type A ends the last side perpendicular, X2.236068 Y14.472136)
G21 G90 G17 G40
G10 L12 P2 R5.
G0 X-10. Y0 Z0
G42 D2 X0 Y0
G1 X20. F500.
X0 Y10.
G40 X-10. Y10.
M30
