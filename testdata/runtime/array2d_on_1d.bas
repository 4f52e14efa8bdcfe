// A fast path that served the first index would read past the end here.
dim v[10]
v[1] = 2
print v[1, 2] // expect-runtime-error: array 'v' has 1 dimension but 2 indices were given
