dim a[3]
print a["1"] // expect-runtime-error: array index must be a number, not a string
