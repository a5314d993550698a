( O-word control flow as LinuxCNC runs it: if/elseif/else, while with  )
( break and continue, do-while, repeat; each step says where it is.    )
#1 = 2
o101 if [#1 EQ 1]
  (debug, wrong branch one)
o101 elseif [#1 EQ 2]
  (debug, elseif #1)
o101 else
  (debug, wrong branch else)
o101 endif
#2 = 0
o102 while [#2 LT 10]
  #2 = [#2 + 1]
  o103 if [#2 EQ 2]
    o102 continue
  o103 endif
  o104 if [#2 EQ 4]
    o102 break
  o104 endif
  (debug, while #2)
o102 endwhile
#3 = 5
o105 do
  (debug, do #3)
  #3 = [#3 + 1]
o105 while [#3 LT 3]
o106 repeat [3]
  #4 = [#4 + 1]
  (debug, repeat #4)
o106 endrepeat
o107 repeat [0]
  (debug, never)
o107 endrepeat
M2
