( Compatibility: in the style of LinuxCNC/linuxcnc nc_files/m70m72-demo.ngc - )
( the caller saves its modes with M70 around a sub that does not know about )
( them, and puts them back with M72. )
( Constructs: M70 at the main level, a sub changing G20 G91 F S, M72. )
( Expected by hand: inside the sub imperial 1, absolute 0, feed 5, rpm 300; )
( after M72: imperial 0, absolute 1, feed 200, rpm 2500. )
o<show> sub
  (DEBUG, imperial=#<_imperial> absolute=#<_absolute> feed=#<_feed> rpm=#<_rpm>)
o<show> endsub

o<inch_sub> sub
  G20 G91 F5 S300
  o<show> call
o<inch_sub> endsub

G21 G90 F200 S2500
M70
o<inch_sub> call
M72
o<show> call
M2
