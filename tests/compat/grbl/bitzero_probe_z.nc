; Compatibility: in the style of vsergeev/nomad3-cncjs-macros
; bitzero-v2-probe-z.macro.nc (a CNCjs macro for a grbl router), as the
; sender streams it: its %CONSTANTS and [expressions] are the sender's and
; are sent as numbers (plate 15.5 mm, probe 20 mm at F100 then 5 mm at F50,
; travel F300, safe height 15 mm); the modal state it saves comes from $G.
; Constructs: $G, M5, G21, G91 probing, G38.2 twice with a G1 back-off, G4 P
; in seconds, G10 L20 without P (the active system, grbl's P0), the restore
; line of the saved modes.
; Scene: the plate's face at machine Z -60 (plate_z60.toml); the tool starts
; 15 mm above it at machine X-200 Y-200 Z-45.
; Expected by hand: both touches latch Z -60 exactly ([PRB:..,-60.000:1]);
; G10 L20 Z15.5 makes the present point (where the slow probe stopped) read
; Z 15.5, and the 15 mm retract in G91 ends at work Z 30.5 exactly, machine
; Z -45 less the few micrometres the stop ran past the contact (tolerance
; 0.01). $G reads the modes the macro restored: G0 G54 G17 G21 G90 G94 M5 M9.
G53 G0 X-200 Y-200 Z-45
$G
M5
G21
G91
G38.2 Z-20 F100
G1 Z2 F300
G38.2 Z-5 F50
G4 P0.1
G10 L20 Z15.5
G4 P0.1
G91
G1 Z15 F300
G54 G17 G21 G90 G94 M5 M9
$G
M2
