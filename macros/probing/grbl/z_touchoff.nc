(skipnc probing library, grbl family: Z touch-off with the probe in the)
(spindle. grbl has no macros, so this is a ready-to-send file: edit the)
(two G53 lines to a safe height and a point above the surface on your)
(machine [here the plate of examples/probing_cycles/part.scene.toml, its)
(top at machine Z-229.87, under X-60 Y10.5]. It probes down with G38.2 at)
(200 mm/min, backs off 1 mm, probes again at 10 mm/min and makes the point)
(where it stopped G54 Z0 with G10 L20, then lifts 5 mm. Written for skipnc;)
(see docs/probing-cycles.md.)
G21 G90 G17 G94
G53 G0 Z0
G53 G0 X-60 Y10.5
G91 G38.2 Z-100 F200
G0 Z1
G38.2 Z-2 F10
G90 G10 L20 P1 Z0
G91 G0 Z5
G90
M2
