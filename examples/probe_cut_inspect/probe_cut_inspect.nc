%
O2030 (PROBE CUT INSPECT)
(Written for skipnc in the output format of the Autodesk Fusion generic)
(Fanuc post, fanuc.cps [its probing cases, protectedProbeMove,)
(getProbingArguments, the print-results DPRNT framing, its tool change)
(and milling blocks], run unmodified with -I macros/probing on)
(cell.machine.toml with block.scene.toml. The one line not from the)
(post is N20: the ball's calibration, kept in the control's memory.)
(The block's top face is meant at G54 X0 Y0 Z0 [machine X-100 Y20)
(Z-200]; it sits at X-99.588 Y19.713 Z-200.153.)
(1. PROBE1, probing-xy-rectangular-boss with S1.: the block's X and Y)
(centre into G54: #5221 = -100 + 0.412 = -99.588, #5222 = 20 - 0.287 =)
(19.713; #138 = 60, the last call's width. PROBE2, probing-z with S1.:)
(the top, 0.153 low, into G54: #5223 = -200 - 0.153 = -200.153.)
(2. POCKET1: T1 clears a 40 x 30 pocket 5 deep at G54 X0 Y0 [tool)
(path 30 x 20, five passes 5 apart, then the contour].)
(3. INSPECT1-3 with print results: the top at X-30 Y15 reads Z0, the)
(floor at X0 Y0 reads Z-5, the pocket reads 40 wide centred on X0 and)
(30 wide on Y0 [H0.05 M0.05 pass]. Last results: #136 = 0, #138 = 30,)
(#141 = 0, #143 = 0, #145 = 0, #148 = 0. The results file is)
(probe_cut_inspect.dprnt; G54 is left as step 1 set it.)
N10 G90 G94 G17 G49 G40 G80
N15 G21
N20 #550=1.
N25 G53 G0 Z0.
(PROBE1)
N30 T20 M6
N35 G54 G0 X0. Y0.
N40 G43 Z50. H20
N45 G65 P9832
N50 G65 P9810 Z5. F1000.
N55 G65 P9812 Z-5. X80. R5. Q5. S1.
N60 G65 P9812 Z-5. Y60. R5. Q5. S1.
N65 G65 P9810 Z50.
(PROBE2)
N70 G0 X-30. Y15.
N75 G65 P9810 Z5. F1000.
N80 G65 P9811 Z0. Q5. S1.
N85 G65 P9810 Z50.
N90 G65 P9833
N95 G53 G0 Z0.
(POCKET1)
N100 T1 M6
(T1 D=10. CR=0. - ZMIN=-5. - FLAT END MILL)
N105 S8000 M3
N110 G54 G0 X-15. Y-10.
N115 G43 Z15. H1
N120 G0 Z5.
N125 G1 Z-5. F300.
N130 X15. F1000.
N135 Y-5.
N140 X-15.
N145 Y0.
N150 X15.
N155 Y5.
N160 X-15.
N165 Y10.
N170 X15.
N175 Y-10.
N180 X-15.
N185 Y10.
N190 X15.
N195 G0 Z15.
N200 M5
N205 G53 G0 Z0.
(INSPECT1)
N210 T20 M6
N215 G54 G0 X-30. Y15.
N220 G43 Z50. H20
N225 G65 P9832
PCLOS
POPEN
DPRNT[START]
DPRNT[RESULTSFILE*SETUP1-RESULTS]
DPRNT[TOOLPATHID*104]
DPRNT[CYCLEDEPTH*0.]
N230 G65 P9810 Z5. F1000.
N235 G65 P9811 Z0. Q5. H0.05 W2.
N240 G65 P9810 Z50.
(INSPECT2)
DPRNT[TOOLPATHID*105]
DPRNT[CYCLEDEPTH*-5.]
N245 G0 X0. Y0.
N250 G65 P9810 Z-2. F1000.
N255 G65 P9811 Z-5. Q5. H0.05 W1.
N260 G65 P9810 Z50.
(INSPECT3)
DPRNT[TOOLPATHID*106]
DPRNT[CYCLEDEPTH*-3.]
N265 G65 P9810 Z-3. F1000.
N270 G65 P9812 X40. Q5. H0.05 M0.05 W1.
N275 G65 P9812 Y30. Q5. H0.05 M0.05 W1.
N280 G65 P9810 Z50.
DPRNT[END]
PCLOS
N285 G65 P9833
N290 G53 G0 Z0.
N295 M30
%
