( Compatibility: in the style of verser-git/probe_screen_v2.8, )
( psng/macros/psng_probe_tool_setter.ngc - a probe-screen tool-setter cycle. )
( Constructs: a sub with M73 [auto-restore] and M71 before endsub, )
( #<_ini[SECTION]NAME> and #<_hal[pin]> reads, G53 G0 moves, G92.1, G49, )
( G10 L20 P0 Z[hal], a probing sub returning a value [endsub [v], #<_value>], )
( "O1 else if" chains ending in [ABORT, ...], G38.3 then G38.2. )
( Expected by hand: the sub goes to machine Z = MAX_LIMIT 0 + offset -10 = -10, )
( then X-250 Y-150 [TOOLSENSOR], Z-90; G10 L20 P0 Z-90 [the HAL pin] makes )
( the G54 Z offset -90 - [-90] = 0. The setter closes at machine Z -100 [scene]: )
( the fast G38.3 and the slow G38.2 both latch Z -100, in G54 with no tool )
( length: #5063 = -100, #5070 = 1; the sub returns 1 [#<_value>], #100 keeps )
( the slow touch. After M71 the endsub restores nothing [the sub ends in G90 )
( itself: #101 = #<_absolute> = 1]; the machine rests at the setter, Z -90. )
o<ts_probe_z> sub
  G91 G38.3 Z-[#1] F[#<_ini[TOOLSENSOR]SEARCH_VEL>]
  G90
  O10 if [#5070 EQ 0]
    o<ts_probe_z> return [-2]
  O10 endif
  G91 G0 Z2
  G38.2 Z-4 F[#<_ini[TOOLSENSOR]PROBE_VEL>]
  G90
o<ts_probe_z> endsub [1]

o<ts_cycle> sub
  M73
  G90
  G53 G0 Z[#<_ini[AXIS_Z]MAX_LIMIT>+#<_ini[PROBE_SCREEN]Z_SAFE_TRAVEL_OFFSET>]
  O20 if [#<_hal[probe.chk_arm_enable]> GT 0]
    (ABORT, no arm on this machine)
  O20 else
    G53 G0 X[#<_ini[TOOLSENSOR]X>] Y[#<_ini[TOOLSENSOR]Y>]
  O20 endif
  G53 G0 Z[#<_ini[TOOLSENSOR]Z>]
  G92.1
  G49
  G10 L20 P0 Z[#<_hal[axis.z.pos-cmd]>]
  o<ts_probe_z> call [#<_ini[TOOLSENSOR]MAXPROBE>]
  O1 if [#<_value> EQ -1]
    M72
    (ABORT, Probe already tripped when starting G38.3 move)
  O1 else if [#<_value> EQ -2]
    M72
    (ABORT, Probe failed to make contact with Tool Sensor)
  O1 endif
  #100 = #5063
  G53 G1 Z[#<_ini[TOOLSENSOR]Z>] F[#<_ini[TOOLSENSOR]RAPID_SPEED>]
  M71
o<ts_cycle> endsub

G21 G90 G54
o<ts_cycle> call
#101 = #<_absolute>
#102 = #<_value>
M2
