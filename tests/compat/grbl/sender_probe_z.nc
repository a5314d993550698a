; Compatibility: in the style of 418dreamworks/grbl-server macros/probe_z.py
; (a sender's Z zero macro: each line it sends, waiting for Idle between):
; relative mode, a fast probe, a back-off with G0, a slow probe, back to
; absolute, the plate's thickness into G54 Z with G10 L20 P1, a raise.
; Constructs: G91 G38.2 at F50 then F10, G0 back-off in G91, G90, G10 L20 P1
; with three decimals, G0 Z in the new G54, $# read by the sender after it.
; Scene: the plate's face at machine Z -60 (plate_z60.toml); start at
; machine Z -50, 10 mm above it.
; Expected by hand: both touches latch Z -60 ([PRB:...,-60.000:1]); G10 L20
; P1 Z22 makes the stop point read Z 22, so G0 Z32 ends 10 mm above it: work
; Z 32, machine Z -50 less the slow stop's overrun (F10: under a micrometre
; of deceleration plus the period; tolerance 0.01). $# gives G54 X and Y 0
; and Z = stop - 22 = -82.000 to grbl's 3 decimals, [PRB:..,-60.000:1].
G53 G0 X-100 Y-100 Z-50
G91
G38.2 Z-11 F50
G0 Z2.5
G38.2 Z-3 F10
G90
G10 L20 P1 Z22.000
G0 Z32.000
$#
M2
