( Compatibility: in the style of kcjengr/probe_basic )
( config/probe_basic/subroutines/probe_z_minus.ngc - find the stock top with )
( a fast then a slow G38.2 and hand back the finish height. )
( Constructs: an o<name> sub with positional arguments named into locals, )
( #5422 [the current Z], G91 with a modal F before G38.2, #5063 and the )
( #5070 check with an early o<name> return, o-if around the slow probe, a )
( DEBUG comment with parameters, #1009 for the screen, endsub [value] read )
( back as #<_value> by the caller. )
( Scene: the stock top at machine Z -100 [plane_z100.toml]; G54 is zero; )
( the probe starts at Z -90. Arguments: tool 99, 20 mm of travel, 2 mm )
( clearance, F10 slow, F300 fast. )
( Expected by hand: the fast probe touches at Z -100 [#5063 = -100 to the )
( 1 ms sampling of lcnc_mill, 5 um at F300], the sub goes to -98, the slow )
( probe [G38.2 Z-4 from -98] touches -100 again: #1009 = -100, the finish )
( height -98 comes back as #<_value> [#100] and the machine rests at -98. )
o<probe_z_minus> sub
  #<probe_tool_number> = #1
  #<max_z_distance> = #2
  #<z_clearance> = #3
  #<probe_slow_fr> = #4
  #<probe_fast_fr> = #5
  #<z> = #5422
  G91
  F[#<probe_fast_fr>]
  G38.2 Z-[#<max_z_distance>]
  #<z_minus_probed> = #5063
  o100 if [#5070 EQ 0]
    G90
    G0 Z#<z>
    o<probe_z_minus> return
  o100 endif
  G90
  G0 Z[#<z_minus_probed> + #<z_clearance>]
  o110 if [#<probe_slow_fr> GT 0]
    G91
    F[#<probe_slow_fr>]
    G38.2 Z-[#<z_clearance> * 2]
    #<z_minus_probed> = #5063
    (DEBUG, probed #5063 now at #<_z>)
    G90
    G0 Z[#<z_minus_probed> + #<z_clearance>]
  o110 endif
  #1009 = #<z_minus_probed>
  #<z_finish_height> = [#<z_minus_probed> + #<z_clearance>]
o<probe_z_minus> endsub [#<z_finish_height>]

G21 G90 G54
G0 X0 Y0 Z-90
o<probe_z_minus> call [99] [20] [2] [10] [300]
#100 = #<_value>
M2
