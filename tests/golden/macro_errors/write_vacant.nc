(#0 is always vacant and cannot be written: alarm 116)
#0=1.
M30
