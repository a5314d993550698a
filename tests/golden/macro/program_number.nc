%
O1234 (#4115: the running program number, #4114: the last sequence number)
N7 #100=#4115
#101=#4114
M98 P5678
M30
O5678
N12 #102=#4115
#103=#4114
M99
%
