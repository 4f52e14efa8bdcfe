dim a[2]
x = a + 1 // expect-runtime-error: cannot add an array and a number
