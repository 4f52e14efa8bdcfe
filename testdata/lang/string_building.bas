// Strings built with + in one expression grow in place: the compiler writes each + over the
// temporary on its left, and the last + into a variable or argument takes that temporary's
// string over (kAddLeftDies). A string that another value shares is never changed: an array
// element, a variable, a sub's result.
n = 7
turns = 3
s = "step " + n + "  turns " + turns + "   "
print "[" + s + "]" // expect: [step 7  turns 3   ]
dim a[2]
a[1] = "k"
b = a[1] + "x" + "y"
print a[1]; b // expect: k	kxy
t = "t"
t = ("<" + t) + t
print t // expect: <tt
u = "u"
u = (u + "1") + (u + "2") + u
print u // expect: u1u2u
v = "v"
w = v + "w" + v
print v; w // expect: v	vwv
print Word() + "!" + Word() // expect: word!word
x = 2
y = (x * 3) + x * 4 + 0.5
print y // expect: 14.5
z = 1 + 2 + "3" + 4
print z // expect: 334
for i = 1 to 3
  row = "row " + i + ":"
  row = row + " " + i * i
  print row
next
// expect: row 1: 1
// expect: row 2: 4
// expect: row 3: 9
end

sub Word()
  k = "word"
  return k
