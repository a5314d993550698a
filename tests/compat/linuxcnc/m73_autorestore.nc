( Compatibility: in the style of LinuxCNC/linuxcnc nc_files/m73-demo.ngc - )
( a sub protects its caller's modes with M73, left by endsub or by return. )
( Constructs: M73, G20/G91/F/S changed inside the sub, o.. return inside )
( o.. if, #<_imperial> #<_absolute> #<_feed> #<_rpm> in [DEBUG, ...]. )
( Expected by hand: the caller runs G21 G90 F200 S2500; inside the sub the )
( state is imperial, incremental, F5, S300 [messages 1 and 3]; after endsub )
( [call [0]] and after return [call [1]] the caller's state is back: imperial 0, )
( absolute 1, feed 200, rpm 2500 [messages 2 and 4]. )
o<state> sub
  (DEBUG, imperial=#<_imperial> absolute=#<_absolute> feed=#<_feed> rpm=#<_rpm>)
o<state> endsub

o<inch_sub> sub
  M73
  G20 G91 F5 S300
  o<state> call
  o<early> if [#1 GT 0]
    o<inch_sub> return
  o<early> endif
o<inch_sub> endsub

G21 G90 F200 S2500
o<inch_sub> call [0]
o<state> call
o<inch_sub> call [1]
o<state> call
M2
