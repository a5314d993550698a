(No tool length offset on a lathe: the T code offsets the tool)
G43 H1 Z10.
M30
