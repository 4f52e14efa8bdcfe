n = 5
print n[0] // expect-runtime-error: 'n' is not an array (it holds a number)
