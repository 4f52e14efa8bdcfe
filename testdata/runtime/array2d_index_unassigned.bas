dim g[2, 3]
g[1, 1] = 5
print g[1, k] // expect-runtime-error: variable 'k' is used before it is given a value // expect-warning: variable 'k' is read but never assigned
