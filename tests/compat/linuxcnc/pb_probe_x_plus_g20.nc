( Compatibility: in the style of kcjengr/probe_basic )
( config/probe_basic/subroutines/probe_x_plus_wco.ngc [its inch set of )
( macros: defaults in inches] run from a G20 program on a metric machine: )
( find the stock's left edge with the probe moving X+, and make it X0 of the )
( active work system. )
( Constructs: G92.1, #[5201 + [20 * #5220]] [the active system's X offset, )
( machine units], #5400 against the probe's tool number with a MSG and an )
( early return, #5410 [the tool's diameter, program units], #5420, G91 )
( G38.2 X, #5061 and the #5070 check, a slow second touch, #1006 for the )
( screen, G10 L2 P#5220 X[edge + offset]. )
( Scene: the stock's left face at machine X 50.8 mm [2 in]; the probe's )
( ball, radius 0.1 in [G10 L1 P99 R0.1 under G20 = 2.54 mm in the tool )
( table], closes the circuit when its centre passes X 48.26 mm [1.9 in]. )
( G54 is zero [so the offset added is 0; with a G54 X set, LinuxCNC adds )
( its machine-unit number to the inch edge, as skipnc does]. )
( Expected by hand: from X 1.6 in the fast probe [0.5 in at F10] touches )
( X 1.9 in; the slow probe from 1.8 [0.2 in at F2] touches 1.9 again; the )
( edge is 1.9 + 0.1 = 2.0 in [#1006, to the 1 ms sampling: under 0.0002 )
( in]; G10 L2 P1 X2.0 makes G54 X 2 in, kept as 50.8 in #5221 [machine )
( units, #101], and G0 X0 then goes to machine X 50.8. )
o<probe_x_plus_wco> sub
  #<probe_tool_number> = #1
  #<max_xy_distance> = #3
  #<xy_clearance> = #4
  #<probe_slow_fr> = #8
  #<probe_fast_fr> = #9
  #<calibration_offset> = #10
  G92.1
  #<workspace_x> = #[5201 + [20 * #5220]]
  o100 if [#5400 NE #<probe_tool_number>]
    (MSG, Specified probe tool #<probe_tool_number> not in spindle, aborting)
    o<probe_x_plus_wco> return
  o100 endif
  #<probe_diameter> = #5410
  #<probe_radius> = [#<probe_diameter> / 2]
  #<probe_center_offset> = [#<probe_radius> - #<calibration_offset>]
  #<x> = #5420
  G91
  F[#<probe_fast_fr>]
  G38.2 X[#<max_xy_distance>]
  #<x_plus_probed> = #5061
  o110 if [#5070 EQ 0]
    G90
    G0 X#<x>
    o<probe_x_plus_wco> return
  o110 endif
  G90
  G0 X[#<x_plus_probed> - #<xy_clearance>]
  o120 if [#<probe_slow_fr> GT 0]
    G91
    F[#<probe_slow_fr>]
    G38.2 X[#<xy_clearance> * 2]
    #<x_plus_probed> = #5061
    G90
    G0 X[#<x_plus_probed> - #<xy_clearance>]
  o120 endif
  #<x_plus_zero_edge> = [#<x_plus_probed> + #<probe_center_offset>]
  #1006 = #<x_plus_zero_edge>
  G10 L2 P#5220 X[#<x_plus_zero_edge> + #<workspace_x>]
o<probe_x_plus_wco> endsub

G20 G90 G54
G10 L1 P99 R0.1
T99 M6
G0 X1.6 Y0 Z-0.2
o<probe_x_plus_wco> call [99] [0.5] [0.5] [0.1] [0.1] [0.5] [0] [2] [10] [0]
#101 = #5221
G0 X0
M2
