(A program that is neither in the file nor on the include path: alarm 76)
#1=1
M98 P8999
M30
