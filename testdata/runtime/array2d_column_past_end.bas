dim g[2, 3]
g[1, 2] = 1
print g[0, 4] // expect-runtime-error: index 4 is out of range for 'g' in dimension 2 (valid: 0 to 2)
