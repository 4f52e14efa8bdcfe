dim g[2, 3]
print g[1, -1] // expect-runtime-error: index -1 is out of range for 'g' in dimension 2 (valid: 0 to 2)
