print 10.0 ^ 400 // expect-runtime-error: the result is too large
