// Conditions compile to branches: a comparison is one compare-and-jump, and/or/not become
// jumps without a value, a single-line if skips its else.
x = 5
if x > 3 and x < 10
  print "mid"
elseif x = 0 or not x
  print "zero"
else
  print "big"
endif
if x <> 5 then print "no" else print "yes"
// expect: mid
// expect: yes
