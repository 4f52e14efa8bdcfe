if "a" < 1 then print 1 // expect-runtime-error: cannot compare a string with a number
