// A literal beyond the largest number is an error when the program loads, not infinity.
print 1e999 // expect-error: number too large: 1e999 (the largest is about 1.8e308)
