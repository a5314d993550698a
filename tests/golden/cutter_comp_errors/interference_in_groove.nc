(G41 with D1 = 5 along the top of a groove 4 wide: the offset of the groove's floor, from X25 Y2 to X19 Y2, runs against the floor's programmed direction; the alarm comes when the block after the floor is read, as the control reads ahead: PS0041 on Fanuc)
G21 G90 G17 F100.
G10 L12 P1 R5.
G0 X-10. Y10. Z0
G41 D1 G1 X0 Y0
X20.
Y-3.
X24.
Y0
X40.
G40 Y10.
M30
