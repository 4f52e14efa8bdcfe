dim a[100000, 100000] // expect-runtime-error: array 'a' is too large (more than 67108864 elements)
