s = "abc"
print s * 2 // expect-runtime-error: '*' needs numbers, not a string
