%
O2026 (PRINT RESULTS)
(Written for skipnc in the output format of the Autodesk Fusion generic)
(Fanuc post, fanuc.cps, with print results on: its POPEN, DPRNT[START],)
(DPRNT[RESULTSFILE*..] header before the first probing operation, the)
(DPRNT[TOOLPATHID*..] and DPRNT[CYCLEDEPTH*..] lines of each, the cycles)
(with W2. then W1., DPRNT[END] and PCLOS at the end. Run with --dprnt;)
(probe.vars holds #550 = 1. The part as in the other cases: CAD = true +)
([0.123, 0.044, 0.37]. The bore, W2.: component 1, feature 1, size 40)
(nominal, 40 read, 0 off; X 0 nominal, -0.123 read; Y 0, -0.044. The top)
(face, W1., after S1. moved G54 X Y onto the bore: feature 2, Z 0, -0.37.)
(CYCLEDEPTH is the post's z - cycle depth + the tool's radius: the bore)
(measured at Z-10., the ball 2 across: -9.; the top face at Z0.: 1.)
(The results file is print_results.dprnt, every line derived so.)
N10 G90 G94 G17 G49 G40 G80
N15 G21
N20 G53 G0 Z0.
N25 T20 M6
N30 G54 G0 X0. Y0.
N35 G43 Z50. H20
N40 G65 P9832
PCLOS
POPEN
DPRNT[START]
DPRNT[RESULTSFILE*SETUP1-RESULTS]
DPRNT[TOOLPATHID*101]
DPRNT[CYCLEDEPTH*-9.]
N45 G65 P9810 Z-10. F1000.
N50 G65 P9814 D40. Q5. W2. S1.
N55 G65 P9810 Z50.
DPRNT[TOOLPATHID*102]
DPRNT[CYCLEDEPTH*1.]
N60 G0 X20. Y-20.
N65 G65 P9810 Z5. F1000.
N70 G65 P9811 Z0. Q5. W1. S1.
N75 G65 P9810 Z50.
DPRNT[END]
PCLOS
N80 G65 P9833
N85 G53 G0 Z0.
N90 M30
%
