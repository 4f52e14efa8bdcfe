// Two values side by side with nothing between them (rb-missing-operator): which operator or
// separator is missing. diagnostics/check.t shows the columns, the range and the fix-its.
n = 5
s = "moves"
// print: '+' where text is joined (the same as ','), ',' between two other values.
print "reached in " + n " moves" // expect-error: missing '+' between 'n' and " moves"
print "moves: " n // expect-error: missing '+' between "moves: " and 'n'
print "a" "b" // expect-error: missing '+' between "a" and "b"
print n "b" // expect-error: missing '+' between 'n' and "b"
print "a"n // expect-error: missing '+' between "a" and 'n'
print n 2 // expect-error: missing ',' between 'n' and '2'
print 1 2 // expect-error: missing ',' between '1' and '2'
print n s // expect-error: missing ',' between 'n' and 's'
print (n + 1) (n + 2) // expect-error: missing ',' between '(n + 1)' and '(n + 2)'
print "n = "; n " moves"; n // expect-error: missing '+' between 'n' and " moves"
// Assignments: '+' joins text; a number or a parenthesis before a name or a parenthesis is a
// product, as algebra writes 2n and (a + b)c; '+' between any other two values.
msg = "x = " n // expect-error: missing '+' between "x = " and 'n'
msg = n " moves" // expect-error: missing '+' between 'n' and " moves"
msg = "a" "b" // expect-error: missing '+' between "a" and "b"
msg = ("n = " + n) s // expect-error: missing '+' between '("n = " + n)' and 's'
msg += " and " n // expect-error: missing '+' between " and " and 'n'
total = 2 n // expect-error: missing '*' between '2' and 'n'
total = 2n // expect-error: missing '*' between '2' and 'n'
total = 1.5 n // expect-error: missing '*' between '1.5' and 'n'
total = (n + 1) n // expect-error: missing '*' between '(n + 1)' and 'n'
total = 2 (n + 1) // expect-error: missing '*' between '2' and '(n + 1)'
total = (n + 1) (n - 1) // expect-error: missing '*' between '(n + 1)' and '(n - 1)'
total = 3 abs(n) // expect-error: missing '*' between '3' and 'abs(n)'
total = abs(n) n // expect-error: missing '*' between 'abs(n)' and 'n'
total = n 2 // expect-error: missing '+' between 'n' and '2'
total = n n // expect-error: missing '+' between 'n' and 'n'
total = 1 2 // expect-error: missing '+' between '1' and '2'
total = n + 1 n // expect-error: missing '*' between '1' and 'n'
dim a[3]
a[1] = a[2] n // expect-error: missing '+' between 'a[2]' and 'n'
if n > 1 then msg = "n = " n // expect-error: missing '+' between "n = " and 'n'
if n > 1 then print "big" n else print "small" // expect-error: missing '+' between "big" and 'n'
// A long value is cut in the message.
msg = "a string far longer than forty characters, cut" n // expect-error: missing '+' between "a string far longer than forty chara..." and 'n'
// The commands whose arguments are a print list start with coordinates: ','.
xyString 10, 20, "n = " n // expect-error: missing ',' between "n = " and 'n'
xyString 10 20, "n" // expect-error: missing ',' between '10' and '20'
// return with a value.
call Moves(3)
sub Moves(k)
  return "moves: " k // expect-error: missing '+' between "moves: " and 'k'
endsub
