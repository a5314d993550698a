(Fanuc system variable names: #_ABSIO[n] = #5000+n, #_ABSMT[n] = #5020+n,)
(#_ABSOT[n] = #5040+n, #_WZG54[n] = #5220+n, #_WZCMN[n] = #5200+n,)
(#_PRTSA = #3901; a plain name is an ordinary named variable)
G21 G90 G54
#_WZG54[1]=10.
#_WZCMN[2]=0.5
G0 X1. Y2. Z3.
#100=#_ABSIO[1]
#101=#_ABSMT[1]
#102=#_ABSOT[2]
#103=#5221
#104=#5202
#_PRTSA=12
#105=#3901
#<DEPTH>=4.5
#106=#<DEPTH>*2
M30
