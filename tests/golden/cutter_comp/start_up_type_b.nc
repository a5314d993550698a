(Start-up of type B, 5003#0 SUP = 1 in the machine file: at the outer corner of 90 degrees between the start-up move and the first side the start-up ends at the intersection of their offset lines, X-5 Y5, not perpendicular to the side as type A, X0 Y5; the cancel of type B ends the side at the intersection with the offset of the G40 move, X25 Y5)
G21 G90 G17 G40
G10 L12 P1 R5.
G0 X0 Y-10. Z0
G41 D1 Y0
G1 X20. F300.
G40 Y-10.
M30
