// A number computed into a variable that holds a string replaces the string: the text is let
// go (its last holder frees it) and other holders keep theirs. Every arithmetic and comparison
// form that writes a number straight into its destination.
s = "text"
s = 2 + 3
print s // expect: 5
t = "shared"
u = t
t = 1.5 * 2
print t, " ", u // expect: 3 shared
v = "x"
v = 10 / 4
print v // expect: 2.5
w = "y"
w = 7 - 9
print w // expect: -2
m = "z"
m = 17 % 5
print m // expect: 2
c = "cmp"
d = c
c = 1 < 2
print c, " ", d // expect: 1 cmp
p = "pow"
p = 2 ^ 10
print p // expect: 1024
big = "big"
big = 9223372036854775807 + 1
print big > 0 // expect: 1
for i = 1 to 3
  r = "r" + i
  r = i * i
next
print r // expect: 9
