(G40/G41/G42 on a lathe: the tool-nose radius compensation state, read)
(back through #4007.)
G50 X100. Z50.
G42
#101 = #4007
G41
#102 = #4007
G40
#103 = #4007
#104 = #4005 (G99 at power-on)
#105 = #4002 (G97 at power-on)
#106 = #4016 (G18 at power-on)
M30
