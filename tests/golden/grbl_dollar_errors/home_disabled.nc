( $H with $22 = 0 [grbl's default: homing not enabled] is error:5. )
( grbl3 keeps the default, so the $H of a sender's start file is refused. )
$H
M2
