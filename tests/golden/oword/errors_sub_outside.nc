( A named subroutine's file is looked for inside the include folders only, as M98's programs: )
( a name that climbs out of the folder is refused, though ../outside_sub.ngc holds that sub. )
o<../outside_sub> call
M2
