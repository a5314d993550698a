(#3000 = n stops with alarm 3000 + n and the comment as its message)
#1=57
IF[#1GT50]THEN#3000=#1(PROBE NOT CALIBRATED)
M30
