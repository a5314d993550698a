%
O02026 (PRINT RESULTS)
(Written for skipnc in the output format of the Autodesk Fusion "HAAS -)
(Next Generation Control" post [haas_vf2_inspect_surface_ENSTA.cps of)
(ThomasLeMezo/enstabretagne-inventor-cam] with print results on: the)
(probe switched on at each operation's start and off at its end, the)
(header of inspectionCreateResultsFileHeader after the first one's)
(G65 P9832 [PCLOS and POPEN as blocks, then DPRNT[START] and)
(DPRNT[RESULTSFILE*..]], before each cycle writeProbingToolpathInformation's)
(TOOLPATHID and CYCLEDEPTH, inspectionWriteCADTransform's G331 line and)
(inspectionWriteWorkplaneTransform's G330 line, and onClose's DPRNT[END])
(and PCLOS. The part's CAD origin and the work plane are G54's, so both)
(transforms print A0. B0. C0. X0. Y0. Z0. [3 decimals, trailing zeros)
(dropped]; their N is #172, which the library leaves alone: vacant here,)
(printed 0 with a space for the sign. The cycles and their lines as in)
(../print_results.nc: the bore, W2., component 1 feature 1, size 40 read)
(40, X -0.123, Y -0.044; the top face, W1., after S1. moved G54 X Y onto)
(the bore, feature 2, Z -0.37. CYCLEDEPTH: z - cycle depth + the tool's)
(radius, -10 + 1 and 0 + 1. The results file is print_results.dprnt.)
N10 G90 G94 G17
N15 G21
N20 G53 G0 Z0.
N25 G53 G0 X0. Y0.
N30 T20 M6
N35 G54
N40 G0 X0. Y0.
N45 G43 Z50. H20
N50 G65 P9832
N55 PCLOS
N60 POPEN
DPRNT[START]
DPRNT[RESULTSFILE*SETUP1-RESULTS]
DPRNT[TOOLPATHID*101]
DPRNT[CYCLEDEPTH*-9.]
DPRNT[G331*N#172[60]*A0.*B0.*C0.*X0.*Y0.*Z0.]
DPRNT[G330*N#172[60]*A0.*B0.*C0.*X0*Y0*Z0*I0*R0]
N65 G65 P9810 Z-10. F1000.
N70 G65 P9814 D40. Q5. W2. S1.
N75 G65 P9810 Z50.
N80 G65 P9833
N85 G0 X20. Y-20.
N90 G65 P9832
DPRNT[TOOLPATHID*102]
DPRNT[CYCLEDEPTH*1.]
DPRNT[G331*N#172[60]*A0.*B0.*C0.*X0.*Y0.*Z0.]
DPRNT[G330*N#172[60]*A0.*B0.*C0.*X0*Y0*Z0*I0*R0]
N95 G65 P9810 Z5. F1000.
N100 G65 P9811 Z0. Q5. W1. S1.
N105 G65 P9810 Z50.
N110 G65 P9833
DPRNT[END]
N115 PCLOS
N120 G53 G0 Z0.
N125 G53 G0 X0. Y0.
N130 M30
%
