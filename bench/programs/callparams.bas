// callparams: 30 rounds of 1,000,000 calls of a sub with three parameters and two locals that
// returns a value (the total starts again at 0 each round); prints 1500007500000.
for r = 1 to 30
  total = 0
  for i = 1 to 1000000
    total = total + Work(i, 2, 3)
  next
next
print total
end

sub Work(a, b, c)
  x = a + b
  y = x * c
  return y
