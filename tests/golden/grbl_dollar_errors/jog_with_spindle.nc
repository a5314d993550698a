( A jog takes only G20/G21, G90/G91, G53, axis words, F and N )
( [Grbl v1.1 Jogging]: an S word is error:16. )
G21 G90
$J=X-10 F500 S1000
M2
