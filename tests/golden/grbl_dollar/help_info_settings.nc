( grbl's report lines [Grbl v1.1 Commands]: $ the help line, $I the build )
( info [VER and OPT; $I= stores the text after the version], $N the two )
( startup lines [kept, not run], $$ every setting as $n=value: grbl 1.1's )
( defaults, the axes' rate, acceleration and travel from grbl3 [X Y 5000 )
( mm/min, 400 mm/s^2, 400 mm; Z 2000, 200, 100], and $110 as set here. )
$
$I=router
$I
$N0=G21 G90
$N
$110=2500
$$
M2
