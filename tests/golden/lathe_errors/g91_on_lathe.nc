(No G91 in G-code system A: U and W are the incremental addresses)
G50 X100. Z50.
G91 X-10.
M30
