(An NC address and a macro statement in one block: alarm 127)
G0 #1=5
M30
