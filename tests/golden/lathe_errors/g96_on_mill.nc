(G96 on a mill: a code of the lathe only)
G96 S200 M03
M30
