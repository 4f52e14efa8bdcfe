// Row 2 of a 2 x 3 array would be the first element past its end.
dim g[2, 3]
g[2, 0] = 1 // expect-runtime-error: index 2 is out of range for 'g' in dimension 1 (valid: 0 to 1)
