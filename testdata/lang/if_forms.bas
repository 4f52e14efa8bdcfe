// Single-line if with then/else, block if/elseif/else/endif, "end if", "if ... then" blocks.
x = 3
if x = 3 then print "single" // expect: single
if x = 4 then print "no" else print "else branch" // expect: else branch
if x > 1 then x = x + 1
print x // expect: 4
if x = 1
  print "one"
elseif x = 4
  print "four" // expect: four
elseif x = 4
  print "not twice"
else
  print "other"
endif
if x then
  print "then-block" // expect: then-block
end if
if 0
  print "no"
else if x = 4
  print "else if" // expect: else if
endif
if x > 0
  if x > 10
    print "big"
  else
    print "nested" // expect: nested
  endif
endif
for i = 1 to 5
  if i = 3 then break
next
print i // expect: 3
