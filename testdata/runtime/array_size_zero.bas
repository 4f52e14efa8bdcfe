n = 0
dim a[n] // expect-runtime-error: array size must be at least 1, not 0
