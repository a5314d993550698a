(Positions cannot be written: alarm 116)
#5021=1.
M30
