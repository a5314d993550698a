( A $ line grbl does not know is error:3 ["'$' system command was not )
( recognized or supported"]: $Q here. )
$Q
M2
