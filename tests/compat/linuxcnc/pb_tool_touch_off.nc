( Compatibility: in the style of kcjengr/probe_basic )
( config/probe_basic/subroutines/tool_touch_off.ngc, after )
( set_g30_position.ngc: the tool setter's place is the G30 position; the )
( sub goes there in machine coordinates, probes fast and slow, and writes )
( the tool's length into the tool table for the tool in the spindle. )
( Constructs: G30.1 and #5181-#5183 [machine units] used with G53, G92.1, )
( #[5203 + [20 * #5220]] [the active system's Z], G49, G91 G38.2 with F on )
( its own line, o<110> if [#5070] / else with a MSG, ABS[], G10 L1 P#5400 )
( [the tool in the spindle], G43 without H [the spindle's tool]. )
( Scene: the tool's tip closes the setter at machine Z -80 [this case's )
( scene]; G54 zero; T1 in the spindle. The setter is at )
( machine X -250 Y -150 and its approach height Z -50, stored by G30.1. )
( Arguments: F300 fast, F20 slow, 50 mm of travel, spindle nose 130 mm )
( below home at the setter's switch point, retract 5 mm. )
( Expected by hand: from Z -50 the fast probe [to -100] touches -80, the )
( retract goes to -75, the slow probe [10 mm] touches -80: #5063 = -80 )
( [#100], the length ABS[130 + -80] = 50 goes to tool 1 [#5403 after G43, )
( #101] and G43 applies it: at G53 Z0 the work Z reads -50 [#<_z>, #102]. )
o<tool_touch_off> sub
  #<fast_probe_fr> = #1
  #<slow_probe_fr> = #2
  #<z_max_travel> = #3
  #<spindle_zero_height> = #5
  #<retract_distance> = #6
  G92.1
  #<workspace_z> = #[5203 + [20 * #5220]]
  #<tool_touch_x_coords> = #5181
  #<tool_touch_y_coords> = #5182
  #<tool_touch_z_coords> = #5183
  G49
  G90
  G53 G0 Z0
  G53 G0 X#<tool_touch_x_coords> Y#<tool_touch_y_coords>
  G53 G0 Z#<tool_touch_z_coords>
  G91
  F #<fast_probe_fr>
  G38.2 Z-[#<z_max_travel>]
  #<z_fast_probe> = #5063
  G0 Z[#<retract_distance>]
  F #<slow_probe_fr>
  G38.2 Z-[#<retract_distance> * 2]
  o<110> if [#5070]
    #<z_slow_probe> = #5063
  o<110> else
    (MSG, Tool Length Offset Probe Failed)
  o<110> endif
  G0 Z[#<retract_distance>]
  G90
  G53 G0 Z0
  #<new_tool_length_offset> = [ABS[#<spindle_zero_height> + #<z_slow_probe>]]
  G10 L1 P#5400 Z[#<new_tool_length_offset>]
  G43
  #100 = #<z_slow_probe>
o<tool_touch_off> endsub

G21 G90 G54
T1 M6
G53 G0 Z0
G53 G0 X-250 Y-150
G53 G0 Z-50
G30.1
G53 G0 Z0
G53 G0 X0 Y0
o<tool_touch_off> call [300] [20] [50] [0] [130] [5]
#101 = #5403
#102 = #<_z>
M2
