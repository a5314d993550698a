(Division by zero: alarm 112)
#1=0
#2=10/#1
M30
