dim a[10]
a[9] = 1
a[10] = 1 // expect-runtime-error: index 10 is out of range for 'a' (valid: 0 to 9)
