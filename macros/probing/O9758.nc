%
O9758 (SKIPNC PROBING LIBRARY - THE RESULTS 50 ABOVE, INTERNAL)
(G65 P9758: copies the results #135-#149 to #185-#199, vacant ones)
(vacant, where the Autodesk Fusion Haas post reads them: its G68)
(X[#185] Y[#186] R[#194], its #[5200 + 20 n + axis + 4] = [that + #194].)
(Every measuring cycle calls it once its results are stored, before its)
(tolerance checks. Written for skipnc: docs/probing-cycles.md.)
#1=135
WHILE[#1LE149]DO1
#[#1+50]=#[#1]
#1=#1+1
END1
M99
%
