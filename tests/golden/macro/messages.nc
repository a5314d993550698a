(Operator messages in the report, in order: MSG comments, #3006 and DPRNT)
(lines; without --dprnt the DPRNT lines go to the messages only)
(MSG,START)
#1=12.3456
#2=-0.5
POPEN
DPRNT[X#1[53]**Y#2[33]*N#3[40]]
DPRNT[RESULT*OK]
PCLOS
#3006=1(TURN THE PART)
G0 X0 (MSG,DONE)
M30
