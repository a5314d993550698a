; Compatibility: in the style of vsergeev/nomad3-cncjs-macros
; bitzero-v2-probe-xy.macro.nc (CNCjs, grbl): find the centre of the probe
; block's bore with the tool inside it, set G54 X0 Y0 there. As the sender
; streams it: the positions it reads (posx, posy: the status report after
; each touch) and the centre it computes are sent as numbers.
; Constructs: G91 G38.2 on X and Y both ways with G4 P pauses, a G1 back-off
; of 1 mm, G90 G1 to the computed centre, G10 L20 with no P (the active
; system) per axis, $# to read the result.
; Scene: the bore's wall, seen by the tool (6.35 mm) as its centre path: the
; circuit closes at X -206 and -194, Y -156 and -144 (bore 15.35 mm about
; X-200 Y-150, less the tool's radius 3.175 = 6 mm each side).
; Expected by hand: the touches latch X-206, X-194, Y-144, Y-156 exactly
; ([PRB:] lines); the stops run the same few micrometres past each contact
; in both directions, so the sender's centre ((X1+X2)/2 = -200.000, Y
; -150.000 from the 3-decimal status) is the bore's; G10 L20 X0 there makes
; G54 X -200, then Y -150: [G54:-200.000,-150.000,0.000]. The retract of
; 15 mm ends at machine Z -35.
G53 G0 X-200 Y-150 Z-50
M5
G21
G91
G38.2 X-15 F100
G4 P0.1
G1 X1 F300
G38.2 X15 F100
G4 P0.1
G90
G1 X-200 F300
G4 P0.1
G10 L20 X0
G4 P0.1
G91
G38.2 Y15 F100
G4 P0.1
G1 Y-1 F300
G38.2 Y-15 F100
G4 P0.1
G90
G1 Y-150 F300
G4 P0.1
G10 L20 Y0
G4 P0.1
G91
G1 Z15 F300
G90
G1 X0 Y0 F300
$#
M2
