// MaxDim(array, dimension): the size of a dimension (1-based), e.g. as the bound of a loop over
// what data built.
data Maps; "one", "two"
data Maps; "three"
for i = 0 to MaxDim(Maps, 1) - 1
  print Maps[i]
next
// expect: one
// expect: two
// expect: three
dim Cube[2, 3, 4]
print MaxDim(Cube, 1); MaxDim(Cube, 2); MaxDim(Cube, 3); MaxDim(Cube)
// expect: 2	3	4	2
print MaxDim(Cube, 4) // expect-runtime-error: argument 2 (dimension) of MaxDim() must be a dimension of the array: 1..3, got 4
