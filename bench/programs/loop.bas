// loop: 10,000,000 iterations of float arithmetic; prints 25000002500000.
x = 0.0
for i = 1 to 10000000
  x = x + i * 0.5
next
print x
