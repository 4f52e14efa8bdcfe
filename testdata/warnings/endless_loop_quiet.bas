// stdin: 7
// Loops whose condition does change, or that end another way: rb check says nothing, and
// each one ends.
rLocate 400, 300
x = 0
while x < 3 // a plain assignment
  x = x + 1
wend
repeat // a for loop inside assigns the variable
  for x = 5 to 6
  next
until x > 6
while x > 0 // in an else branch of a single-line if
  if x > 100 then print "big" else x = x - 2
wend

// What a gosub runs: its routine, and what that routine calls in turn.
n = 0
while n < 3
  gosub Inc
wend
while n < 6
  gosub Outer
wend
while n < 9
  gosub Late // expect: late
  // expect: late
  // expect: late
wend

// What a call runs: a sub that assigns the global (_n), a by-reference argument, a sub used
// as a function.
while n < 12
  call GlobalInc()
wend
while n < 15
  call AddOne(n)
wend
while n < 18
  y = NextN()
wend
while n < 21 // a by-reference argument of a sub used as a function
  y = Through(n)
wend

// Ways out other than the condition: break, goto, end in what it calls (below, last).
stop = 0
while stop = 0
  if n > 0 then break
wend
while stop = 0
  goto Out
wend
Out:

// Conditions anything may change: a sensor, the timer, random numbers, array elements.
dim flags[3]
i = 0
while flags[i] = 0
  flags[i] = 1
wend
while rFeel() = 99
  rTurn 1
wend
t = timer()
while timer() < t
wend
while random(10) = 99
wend

// Statements that assign: input, an output argument.
v = 0
while v = 0
  input "a number: ", v // expect: a number: 7
wend
mx = -1
repeat
  readMouse mx, my
until mx <> -1

// Constant conditions are written on purpose.
while 1
  break
wend
repeat
until 1

print n, v // expect: 217
gosub Finish
while stop = 0 // ends through the end in Finish
  gosub Finish
wend
end

Inc:
  n = n + 1
return

Outer:
  gosub Inc
return

Late:
  if n > 100 then return
  print "late"
  n = n + 1
return

Finish:
  if n > 0 then end
return

sub GlobalInc()
  _n = _n + 1
endsub

sub AddOne(&value)
  value = value + 1
endsub

sub NextN()
  _n++
  return _n
endsub

sub Through(&value)
  value = value + 1
  return value
endsub
