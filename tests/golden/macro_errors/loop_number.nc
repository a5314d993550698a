(Loop numbers are 1 to 3: alarm 126)
WHILE[1EQ1]DO4
END4
M30
