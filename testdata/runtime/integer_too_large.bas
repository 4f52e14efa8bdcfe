print 1e300 & 1 // expect-runtime-error: number too large for an integer operation
