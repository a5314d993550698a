%
O9832 (PROBE ON - OWN MACRO FOR THE COMPATIBILITY PROGRAMS)
(In the style of the call Haas posts write before probing, G65 P9832;)
(not Renishaw's or Haas's macro. The scene's probe is always live: this)
(one only records that it was switched on, in #150.)
#150 = 1
M99
%
