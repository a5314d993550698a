(#200 is not a variable of this control: alarm 115)
#1=#200
M30
