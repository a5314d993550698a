( Compatibility: in the style of LinuxCNC/linuxcnc nc_files/gridprobe.ngc - )
( probe a grid of points, each result written to a probe log file. )
( Constructs: [PROBEOPEN file] / [PROBECLOSE], nested o.. while loops, an )
( o.. if / else on the row parity, G38.2 with modal F, metric here [G21]. )
( Expected by hand: 3 columns x 2 rows = 6 touches of the plane at machine )
( Z -100 [scene]; G54 is zero, so each #5063 = -100, within the 8.3 um the )
( axis moves in one 1 ms servo period at F500, and the probe log holds 6 )
( lines, written into --log-dir: the run names the file and its line count )
( in a message. The last point is row 1 [odd: right to left], column 0, at X 0, )
( Y 10; the machine rests at Z -90 [the safety height]. )
G21 G90 F500
#1 = 0      (X start)
#2 = 10     (X step)
#3 = 3      (X count)
#4 = 0      (Y start)
#5 = 10     (Y step)
#6 = 2      (Y count)
#7 = -90    (Z safety)
#8 = -110   (Z probe limit)
(PROBEOPEN grid.txt)
#9 = 0
G0 Z#7
O1 while [#9 lt #6]
  #10 = 0
  G0 Y[#4 + #5 * #9]
  O2 while [#10 lt #3]
    O3 if [[#9 / 2] - fix[#9 / 2] eq 0]
      G0 X[#1 + #2 * #10]
    O3 else
      G0 X[#1 + #2 * [#3 - #10 - 1]]
    O3 endif
    G38.2 Z#8
    G0 Z#7
    #10 = [#10 + 1]
  O2 endwhile
  #9 = [#9 + 1]
O1 endwhile
(PROBECLOSE)
M2
