x = 3
print MaxDim(x, 1) // expect-runtime-error: argument 1 (array) of MaxDim() must be an array
