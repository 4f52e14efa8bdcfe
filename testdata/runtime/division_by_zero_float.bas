print 1.5 / 0.0 // expect-runtime-error: division by zero
