(A lathe machine file with a Y axis is refused before the run starts)
G00 X10.
M30
