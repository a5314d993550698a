(After two blocks without a plane move the line of line 6 (X10.) ends perpendicular, X10 Y2; the G03 that follows starts on its offset circle of radius 8, X8 Y0, joined by a line, instead of from where the tool is with the wrong radius)
G21 G90 G17 G40
G10 L12 P1 R2.
G0 X-10. Y0 Z0
G41 D1 G1 X0 Y0 F300.
X10.
G4 P10
M8
G3 X0 Y10. I-10. J0
G40 G1 X-10.
M30
