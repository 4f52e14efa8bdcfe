// One mistake, one error: what follows from it is not reported again.
x = (1 + 2 // expect-error: expected ')', found end of line
print x
while k < 3
  for i = 1 to 2
    k = k + 1
wend // expect-error: wend closes a while, but the for at line 5 is still open (missing next)
print k
