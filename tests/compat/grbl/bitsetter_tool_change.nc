; Compatibility: in the style of vsergeev/nomad3-cncjs-macros
; bitsetter-change-tool.macro.nc (CNCjs, grbl): at a tool change, go to the
; tool setter in machine coordinates, probe fast then slow, and shift G54 Z
; by the new tool's length difference against the reference the sender
; kept. As the sender streams it for a second tool: the reference (the first
; tool's touch, machine Z -75.000) and the offset it computes are numbers;
; M0 is the pause for the manual change (grbl stops; the operator resumes).
; Constructs: G53 G1 to the change and setter positions, M0, G4 P0.1,
; G91 G38.2 twice with G0 back-off, G10 L20 Z from the computed offset,
; the return at safe height through G53 and the saved work position.
; Scene: the new tool touches the setter at machine Z -72 (3 mm longer).
; G54 Z was -100 (set in the machine file); the work position before the
; change was X 50 Y 40 [machine -250, -200].
; Expected by hand: both touches latch Z -72.000; the slow probe stops
; 0.0025 mm past the contact (v^2/2a = 0.0017 mm at F50 and 200 mm/s^2, plus
; the 1 ms period in which the contact is seen), at -72.0025; the sender
; reads mposz -72.002 from the status report, so TOOL_OFFSET = -72.002 -
; (-75.000) = 2.998 and, with posz = mposz + 100 = 27.998, G10 L20
; Z[posz - offset] = Z25.000: G54 Z becomes -72.0025 - 25 = -97.0025, which
; grbl prints as -97.002 (3 mm less deep than -100, to the stop's
; micrometres). The run ends at X 50 Y 40 in G54, machine Z -5.
G53 G0 X-250 Y-200 Z-20
M5
G21
G90
G53 G1 Z-5 F5000
G53 G1 X-125 Y-110 F5000
M0
G90
G53 G1 X-5 Y-3 F5000
G53 G1 Z-65 F800
G4 P0.1
G91
G38.2 Z-20 F100
G0 Z2
G38.2 Z-5 F50
G4 P0.1
G10 L20 Z25.000
G4 P0.1
G90
G53 G1 Z-5 F5000
G1 X50 Y40 F5000
$#
M2
