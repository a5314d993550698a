( A jog needs its own F, never modal [Grbl v1.1 Jogging]: without it, )
( error:22 [feed rate undefined], even after a modal F. )
G1 X-1 F300
$J=X-10
M2
