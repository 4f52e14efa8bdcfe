g = 5
print g[1, 1] // expect-runtime-error: 'g' is not an array (it holds a number)
