print 7 % 0 // expect-runtime-error: division by zero (in %)
