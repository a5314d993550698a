(A held move that ends perpendicular at a flush always goes out: here the X-1. of line 9 -, resumed from X-2 Y10 after two blocks without a plane move, ends at X-1 Y8 when M00 makes the interpreter wait; the end runs against the line's direction, which at a flush is no reason to drop the move - it was dropped without a word)
G21 G90 G17 G40
G10 L12 P1 R2.
G0 X0 Y-10. Z0
G41 D1 G1 X0 Y0 F300.
Y10.
G4 P10
M8
X-1.
M0
G40 X-10.
M30
