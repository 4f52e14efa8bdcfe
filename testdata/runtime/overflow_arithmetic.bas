// Arithmetic that leaves the range of numbers stops the program; no value is ever infinite.
x = 1e300
y = x * x // expect-runtime-error: the result is too large
print y
