( A call to a subroutine that is nowhere: not in this file, no sub_missing.ngc. )
o<sub_missing> call [1]
M2
