(3405#1 DWL = 1: in G99 G04 counts spindle revolutions; at 600 rpm one)
(revolution is 0.1 s. In G98 it is seconds again.)
G97 S600 M03
G99 G04 X3.
G04 P1500
G98 G04 X3.
M30
