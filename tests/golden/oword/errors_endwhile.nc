( An endwhile whose while never ran is an error with its line. )
G0 X1
o5 endwhile
M2
