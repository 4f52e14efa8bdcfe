a = 0
print 10 / a // expect-runtime-error: division by zero
