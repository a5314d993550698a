( Compatibility: a G20 program on a metric machine calling a sub in the )
( style of kcjengr/probe_basic config/probe_basic/subroutines/probe_z_minus.ngc )
( [the sub of pb_probe_z_minus.nc; probe_basic ships an inch and a metric )
( set of its macros]: every length it reads and returns is in inches. )
( Constructs: as pb_probe_z_minus.nc, under G20: #5422, #5063 and the return )
( value in program units [inches] on a mm machine. )
( Scene: the stock top at machine Z -100 mm = -3.93701 in; G54 zero; start )
( at Z -3.5 in [-88.9 mm]. Arguments: 1 in of travel, 0.1 in clearance, )
( F0.5 slow, F12 fast [in/min]. )
( Expected by hand: both touches at Z -3.93701 in [#1009, to the 1 ms )
( sampling: 5 um = 0.0002 in at F12]; the finish height -3.83701 comes back )
( as #<_value> [#100]; the machine rests at -97.46 mm [-3.83701 x 25.4]. )
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

G20 G90 G54
G0 X0 Y0 Z-3.5
o<probe_z_minus> call [99] [1] [0.1] [0.5] [12]
#100 = #<_value>
M2
