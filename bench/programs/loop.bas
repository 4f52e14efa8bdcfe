// loop: 8 rounds of 10,000,000 iterations of float arithmetic (x starts again at 0 each
// round); prints 25000002500000.
for r = 1 to 8
  x = 0.0
  for i = 1 to 10000000
    x = x + i * 0.5
  next
next
print x
