// Values next to each other where the grammar goes on: none of these is a missing operator
// (rb-missing-operator, testdata/errors/missing_operator.bas), and each runs.
n = 3
dim a[4]
a[1] = 7
// print's separators, and print(x)
print "n = ", n // expect: n = 3
print "n ="; n // expect: n =	3
print "n = " + n + " moves" // expect: n = 3 moves
print(n) // expect: 3
print (n) * 2 // expect: 6
// keywords inside a statement: then, else, to, step, mod, and, or
if n > 1 then print "big" else print "small" // expect: big
for i = 1 to 5 step 2
  print i // expect: 1
  // expect: 3
  // expect: 5
next
x = n mod 2 and n or 0
print x // expect: 1
// a sign is an operator: n -1 is n - 1
x = n -1
print x // expect: 2
x = -n
print x // expect: -3
// a space before '(' or '[' still calls or indexes
x = abs (0 - n)
print x // expect: 3
print a [1] // expect: 7
a [2] = a [1] + 1
print a[2] // expect: 8
// a command and its arguments, with commas or in parentheses
rLocate 100, 100
rForward 10
rTurn (45)
xyString 10, 20, "n = ", n; n
// a label, goto and a single-line if's statements
goto Done
print "skipped"
Done: print "done" // expect: done
call Twice(n)
sub Twice(k)
  print k * 2 // expect: 6
  return
endsub
