( A named parameter read before it is set is an error, as in LinuxCNC. )
#<a> = 1
G0 X#<a> Y#<b>
M2
