(skipnc probing library, grbl family: the X and Y zero of G54 on an outer)
(corner, the part's -X and -Y faces, with the probe in the spindle.)
(Ready-to-send: edit the G53 lines to put the probe 6 mm off the corner in)
(X and in Y, below the top, on your machine [here the corner of the plate)
(of examples/probing_cycles/part.scene.toml, machine X-150 Y-100, 5 mm)
(under its top], and the X-1 and Y-1 of the G10 lines to minus your)
(ball's radius. Each face: G38.2 at 200 mm/min, back off 1 mm, G38.2 at)
(10 mm/min, G10 L20 makes the face 0 [the ball's centre at minus its)
(radius], back off 5 mm. Written for skipnc; see docs/probing-cycles.md.)
G21 G90 G17 G94
G53 G0 Z0
G53 G0 X-156 Y-106
G53 G0 Z-84
G91 G0 Y12
G38.2 X10 F200
G0 X-1
G38.2 X2 F10
G90 G10 L20 P1 X-1
G91 G0 X-5
G0 Y-12
G0 X12
G38.2 Y10 F200
G0 Y-1
G38.2 Y2 F10
G90 G10 L20 P1 Y-1
G91 G0 Y-5
G0 X-12
G53 G0 Z0
G90
M2
