%
O9757 (SKIPNC PROBING LIBRARY - PRINT RESULTS, INTERNAL)
(G65 P9757 W.. [D1.] [X1.] [Y1.] [Z1.] [A1.] [K..]: W vacant: nothing. W1)
(the next feature, W2 the next component and its first feature: #564 the)
(component, #565 the feature number. Prints with DPRNT, to the file the)
(program opened with POPEN, the feature's header and one line for each)
(result asked for: D the size #138, X Y Z the position #135 #136 #137 [K)
(1, 2, 3: that axis alone], A)
(the angle #139, each as its nominal [the result less its error, #143,)
(#140-#142, #144], the result and the error, 4 decimals.)
(Written for skipnc: docs/probing-cycles.md.)
IF[#23EQ#0]GOTO99
IF[[#23NE1]AND[#23NE2]]THEN#3000=91(FORMAT ERROR)
IF[#6EQ1]THEN#24=1
IF[#6EQ2]THEN#25=1
IF[#6EQ3]THEN#26=1
IF[#564EQ#0]THEN#564=0
IF[#565EQ#0]THEN#565=0
IF[#23EQ2]GOTO10
#565=#565+1
IF[#564LT1]THEN#564=1
GOTO20
N10#564=#564+1
#565=1
N20DPRNT[-------------------------------------------------------------------]
DPRNT[***COMPONENT*NO#564[20]********************FEATURE*NO#565[20]]
DPRNT[-------------------------------------------------------------------]
IF[#7EQ#0]GOTO30
#31=#138-#143
DPRNT[SIZE*D#31[44]**ACTUAL*#138[44]**DEV*#143[44]]
N30IF[#24EQ#0]GOTO40
#31=#135-#140
DPRNT[POSN*X#31[44]**ACTUAL*#135[44]**DEV*#140[44]]
N40IF[#25EQ#0]GOTO50
#31=#136-#141
DPRNT[POSN*Y#31[44]**ACTUAL*#136[44]**DEV*#141[44]]
N50IF[#26EQ#0]GOTO60
#31=#137-#142
DPRNT[POSN*Z#31[44]**ACTUAL*#137[44]**DEV*#142[44]]
N60IF[#1EQ#0]GOTO99
#31=#139-#144
DPRNT[ANG*#31[44]**ACTUAL*#139[44]**DEV*#144[44]]
N99M99
%
