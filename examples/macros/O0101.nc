%
O0101 (TOP FACE: SETS G54 Z, THEN MEASURES A TOOL ON THE SETTER)
(Scene surface.scene.toml: the part's top face stops the probe's tip at)
(machine Z-123.456, input X0.4; the tool setter's face meets a 60 mm tool)
(at machine Z-240, input X0.1 = SKIP2; #501 = -300.)
N10 G21 G90 G17 G40 G49 G80 G54
N20 G53 G0 Z0
N30 G0 X20. Y20.
N35 G10 L2 P1 Z-120. (the fixture drawing: top face about 120 mm down)
N40 G65 P8811 Z0 S1. (measure it: the top face becomes G54 Z0)
N50 #501=-300. (machine Z of the setter's face)
N60 G53 G0 Z0
N70 G0 X-200. Y-150. (over the setter)
N80 G65 P8801 T12.
N90 G53 G0 Z0
N100 M30
%
