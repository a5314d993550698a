( Subroutines: arguments in #1.., numbered locals saved and restored, )
( named locals per call level, globals, return values, recursion.     )
o<fact> sub
  o1 if [#1 LE 1]
    o<fact> return [1]
  o1 endif
  o<fact> call [#1 - 1]
o<fact> endsub [#1 * #<_value>]

o<scope> sub
  #<local> = 7
  #<_global> = [#<_global> + 1]
  #31 = 31
  (debug, in scope #1 #2 #3 local #<local> level #<_call_level>)
o<scope> endsub

#1 = 100
#<local> = 1
#<_global> = 10
o<scope> call [1] [2]
(debug, after scope #1 local #<local> global #<_global> #31 returned #<_value_returned>)
o<fact> call [5]
(debug, fact #<_value> returned #<_value_returned>)
#5 = EXISTS[#<local>]
#6 = EXISTS[#<nothing>]
(debug, exists #5 #6)
#7 = 3  #8 = #7  G0 X#7  (every value on the line is read before the settings: X0)
(debug, same line #8)
M2
