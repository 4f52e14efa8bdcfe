dim g[2, 3]
k = "1"
print g[k, 1] // expect-runtime-error: array index must be a number, not a string
