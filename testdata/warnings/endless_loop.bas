// rb check warns about a while or repeat loop whose condition tests only variables that
// nothing in the loop changes: once it goes round, it goes round for ever. None of these
// loops runs (their conditions are false at first, or they are never reached).
sides = 4
while sides < 4 // expect-warning: this loop never ends once it repeats: nothing in it changes 'sides'
  print "side"
wend

// Two variables: changing either could end it, and nothing changes either.
a = 1
b = 2
while a > b or abs(a - b) > 5 // expect-warning: this loop never ends once it repeats: nothing in it changes 'a' or 'b'
  print a + b
wend

// A routine that only reads the variable changes nothing.
count = 10
while count < 3 // expect-warning: this loop never ends once it repeats: nothing in it changes 'count'
  gosub Show
wend

// A sub's own variable is not the main program's: Bump sets its own 'count' (use _count).
while count < 10 // expect-warning: this loop never ends once it repeats: nothing in it changes 'count'
  call Bump()
wend

call Wait(0) // expect: once
print "done" // expect: done
end

Show:
  print count
return

sub Bump()
  count = count + 1
endsub

// Inside a sub: the loop's variables are the sub's own.
sub Wait(most)
  waited = 0
  while waited < most // expect-warning: this loop never ends once it repeats: nothing in it changes 'waited' or 'most'
    print "waiting"
  wend
  x = 1
  repeat
    print "once"
  until x = 1 or x > most // expect-warning: this loop never ends once it repeats: nothing in it changes 'x' or 'most'
endsub
