dim g[2, 3]
print g[-1, 2] // expect-runtime-error: index -1 is out of range for 'g' in dimension 1 (valid: 0 to 1)
