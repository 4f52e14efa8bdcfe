// `n = n + 1` when n has no value names n, as any other use of it does.
count = 1
count = count + 1
cuont = cuont + 1 // expect-runtime-error: variable 'cuont' is used before it is given a value; did you mean 'count'?
