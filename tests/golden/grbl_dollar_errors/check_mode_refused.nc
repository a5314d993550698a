( $C [check mode: the program parsed, nothing moved] is refused by name: )
( it is not simulated [alarm not_simulated]. )
$C
M2
