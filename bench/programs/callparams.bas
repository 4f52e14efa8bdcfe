// callparams: 1,000,000 calls of a sub with three parameters and two locals that returns a
// value; prints 1500007500000.
total = 0
for i = 1 to 1000000
  total = total + Work(i, 2, 3)
next
print total
end

sub Work(a, b, c)
  x = a + b
  y = x * c
  return y
