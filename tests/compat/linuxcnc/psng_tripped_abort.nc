( Compatibility: in the style of verser-git/probe_screen_v2.8, )
( psng/macros/psng_probe_tool_setter.ngc with its probing sub's check of the )
( probe input before it moves [the _psng_probe_z family returns -1]. )
( Constructs: #<_hal[motion.probe-input]> as a bit pin, o.. return [-1], )
( #<_value>, M73 then M72 before [ABORT, ...]. )
( Expected by hand: the machine file's HAL pin says the probe is closed, the )
( sub returns -1 before any probing move and the first ABORT of the chain )
( ends the run: alarm 3000 at line 24, the machine still at the start. )
o<tp_probe_z> sub
  O5 if [#<_hal[motion.probe-input]> EQ 1]
    o<tp_probe_z> return [-1]
  O5 endif
  G91 G38.3 Z-[#1] F300
  G90
o<tp_probe_z> endsub [1]

o<tp_cycle> sub
  M73
  G90
  G53 G0 Z[#<_ini[TOOLSENSOR]Z>]
  o<tp_probe_z> call [#<_ini[TOOLSENSOR]MAXPROBE>]
  O1 if [#<_value> EQ -1]
    M72
    (ABORT, Probe already tripped when starting G38.3 move)
  O1 else if [#<_value> EQ -2]
    M72
    (ABORT, Probe failed to make contact with Tool Sensor)
  O1 endif
  M71
o<tp_cycle> endsub

G21 G90 G54
o<tp_cycle> call
M2
