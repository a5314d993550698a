( Nine nested calls run; a tenth is LinuxCNC's "Too many subroutine levels". )
o<d> sub
  o1 if [#1 GT 0]
    o<d> call [#1 - 1]
  o1 endif
o<d> endsub
o<d> call [8]
(debug, nine levels ran)
o<d> call [9]
M2
