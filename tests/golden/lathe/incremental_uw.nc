(G-code system A on lathe2: X/Z absolute, U/W incremental, mixed in one)
(block; X in diameter, so U-10. moves the slide 5 mm.)
G50 X100. Z50.
G00 X80. Z10.
U-10. W-5.
X50. W-2.5
U4. Z0
G98 G01 W-20. F200.
M30
