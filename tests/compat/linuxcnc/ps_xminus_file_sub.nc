( Compatibility: in the style of verser-git/probe_screen_v2, macros/xminus.ngc )
( - an X- edge finder the probe screen calls by name from its own file. )
( Constructs: o<name> call found as name.ngc in the subroutine folder [-I], )
( G92.1, G49, G10 L20 P0 X[#<_hal[axis.0.joint-pos-cmd]>] Y[...], G91 G38.2 )
( with F from a HAL pin, G4 P0.5, a global named parameter set in the sub. )
( Expected by hand: the machine stands at X -20 Y 0; the HAL pins hold the )
( same, so G10 L20 leaves G54 at 0. The fast G38.2 X-15 meets the edge at )
( machine X -30 [scene]; 2 mm back, the slow G38.2 X-4 meets it again: )
( #5061 = #<_edge_x> = -30. The sub ends with G90 G0 back to X -20. )
G21 G90 G54
G0 X-20 Y0 Z-10
o<ps_xminus> call
#100 = #<_edge_x>
M2
