print "a" // expect: a
return // expect-runtime-error: return without gosub or call
