// mFromString array, text, delimiter: the array becomes the fields of the text; fields that
// spell numbers are numbers (a SERVO Magazine listing reads sensor angles this way).
dim A[10]
mFromString A, "10,20.5,abc,,350", ","
print MaxDim(A, 1)
// expect: 5
print A[0] + A[1]; A[2]; "["; A[3]; "]"; A[4] - 360
// expect: 30.5	abc	[		]	-10
mFromString B, "x::y", "::"
print B[0]; B[1]
// expect: x	y
mFromString C, "no delimiter here"
print MaxDim(C, 1); C[0]
// expect: 1	no delimiter here
mFromString D, "1 2", "" // expect-runtime-error: argument 3 (delimiter) of mFromString must not be empty
