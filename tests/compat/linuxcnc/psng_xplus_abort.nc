( Compatibility: in the style of verser-git/probe_screen_v2.8, )
( psng/macros/psng_xplus.ngc - probe toward X+ and give up with [ABORT, ...]. )
( Constructs: M73 in a sub, #<_x> saved, #<_hal[probe.ps_probe_max]> as the )
( search length, a probing sub returning -2 when G38.3 finds nothing, M72 )
( then [ABORT, text] inside an "O1 else if" chain. )
( Expected by hand: nothing in the scene drives the probe input, so the G38.3 )
( X+15 [the HAL pin] ends without contact, #5070 = 0, the sub returns -2 and )
( the [ABORT, ...] ends the run: exit 1, alarm 3000 [user alarm] at line 29; )
( the G1 back to #<x> [line 31] never runs, so the machine rests at X 15 )
( after the search from X 0. )
o<px_probe_x> sub
  G91 G38.3 X[#1] F300
  G90
  O10 if [#5070 EQ 0]
    o<px_probe_x> return [-2]
  O10 endif
o<px_probe_x> endsub [1]

o<px_cycle> sub
  M73
  #<x> = #<_x>
  G90
  o<px_probe_x> call [#<_hal[probe.ps_probe_max]>]
  O1 if [#<_value> EQ -1]
    M72
    (ABORT, Probe already tripped when starting G38.3 move)
  O1 else if [#<_value> EQ -2]
    M72
    (ABORT, Probe failed to make contact with workpiece)
  O1 endif
  G1 X#<x> F#<_ini[TOOLSENSOR]RAPID_SPEED>
  M71
o<px_cycle> endsub

G21 G90 G54 G0 X0 Y0 Z-20
o<px_cycle> call
M2
