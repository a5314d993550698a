(NCT: #5061.. in the work system with G54, G43 H1 and G45 D1; G31 at G31FD = 120 from --param: the end point #5001 lies 2/30 mm of servo lag plus the braking distance past the latch; the next block starts there)
G21 G90 G54 G0 X0 Y0 Z50.
G43 H1 Z10.
G91 G45 X10. D1
G90 G31 X30. F2000.
#100 = #5001
G91 G1 X-5. F500.
M30
