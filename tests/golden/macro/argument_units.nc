(G65 arguments written without a decimal point are in the least input)
(increment of their address: lengths 0.001 mm or 0.0001 inch; D E F H M S T)
(and A B C that are not axes as written; with a point or an expression as is)
G21
#1=10
G65 P7800 X10 Y1.5 Z#1 R5 Q2 I3 D3 F100 S1 A54 M7
#110=#100
#111=#101
#112=#102
#113=#103
#114=#104
#115=#105
#116=#106
#117=#107
#118=#108
#119=#109
G20
G65 P7800 X10 Y1.5
#121=#100
#122=#101
G21
M30
O7800
#100=#24
#101=#25
#102=#26
#103=#18
#104=#17
#105=#4
#106=#7
#107=#9
#108=#19
#109=#1
M99
