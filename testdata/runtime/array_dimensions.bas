dim a[3, 3]
print a[1] // expect-runtime-error: array 'a' has 2 dimensions but 1 index was given
