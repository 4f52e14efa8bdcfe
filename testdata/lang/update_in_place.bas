// A result that replaces its own left operand (`x = x + y`, `n = n + 1`, `n = n - 1`,
// `x = x + 0.5`): every kind of value the variable may hold, every overflow, in main code and
// in a sub, the same as any other assignment.
x = 1.5
y = 2.25
x = x + y
print x // expect: 3.75
i = 2
j = 40
i = i + j
print i // expect: 42
i = i + y
print i // expect: 44.25
n = 9223372036854775807
n = n + 1
print n // expect: 9.22337203685478e+18
m = -9223372036854775807
m = m - 1
print m // expect: -9223372036854775808
m = m - 1
print m // expect: -9.22337203685478e+18
k = 1.5
k = k + 1
k = k - 1
print k // expect: 1.5
f = 3
f = f + 0.5
f = f + 0.25
print f // expect: 3.75
s = "ab"
s = s + "c"
s = s + 1
s = s + 0.5
print s // expect: abc10.5
t = 7
t = t + "x"
print t // expect: 7x
big = 1e308
print UpdateInSub(2) // expect: 13
big = big + 1e308 // expect-runtime-error: the result is too large
end

sub UpdateInSub(v)
  v = v + 1
  v = v + v
  v = v - 1
  v = v + 0.5
  v = v + 7.5
return v
