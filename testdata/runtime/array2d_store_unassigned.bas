dim g[2, 3]
g[1, 1] = v // expect-runtime-error: variable 'v' is used before it is given a value // expect-warning: variable 'v' is read but never assigned
