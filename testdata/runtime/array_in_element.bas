dim a[3]
dim b[2]
a[0] = b // expect-runtime-error: an array cannot be stored in an array element
