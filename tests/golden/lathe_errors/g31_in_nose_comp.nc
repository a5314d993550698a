(G31 with tool-nose radius compensation on: PS0035)
G50 X100. Z50.
G42
G98 G31 U-10. F100.
M30
