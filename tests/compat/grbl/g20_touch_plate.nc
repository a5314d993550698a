; Compatibility: a grbl Z touch-off in inches on a metric grbl, in the style
; of vsergeev/nomad3-cncjs-macros bitzero-v2-probe-z.macro.nc with G20
; instead of G21 (the sender's units set to inches): grbl keeps every offset
; in mm whatever G20/G21 says, and $13 changes only what it reports.
; Constructs: G20 G91 G38.2 with inch distances and feed (inch/min), G10
; L20 P1 Z in inches, $# in mm ($13=0) then in inches ($13=1), $G.
; Scene: the plate's face at machine Z -60 (plate_z60.toml); start at
; machine Z -45.
; Expected by hand: G38.2 Z-1 F4 is 25.4 mm at 101.6 mm/min: the touch
; latches Z -60.000 (mm in [PRB:]); G1 Z0.05 backs off 1.27 mm; the slow
; G38.2 Z-0.2 F2 touches at -60 again. G10 L20 P1 Z0.6102 (15.5 mm plate
; to four decimals) makes the stop point read 0.6102 in = 15.499 mm, so G54
; Z = stop - 15.49908 = -75.501 (the slow stop runs 2 micrometres past
; the contact: F2 in/min, 200 mm/s^2, and the period that sees it). The G91 Z0.5 retract ends at work Z 1.1102 in.
; $G reads G1 G20 and the last F, 12 in/min, in mm/min as grbl keeps it:
; F305 (304.8, no decimals); with $13=1 F12.0 (inch/min, one decimal). $#
; lists G54 Z in mm (-75.501) and, with $13=1, in inches (-2.9725); the
; [PRB:] Z -60 mm is -2.3622 in.
G53 G0 X-200 Y-200 Z-45
G20
G91
G38.2 Z-1 F4
G1 Z0.05 F12
G38.2 Z-0.2 F2
G10 L20 P1 Z0.6102
G1 Z0.5 F12
G90
$G
$#
$13=1
$G
$#
M2
