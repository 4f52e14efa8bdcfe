// The element count of an array is checked before it is multiplied: 65536 x 2^48 is 2^64,
// which would wrap to 0 and leave every index unchecked against the real storage.
dim a[65536, 281474976710656] // expect-runtime-error: array 'a' is too large (more than 67108864 elements)
a[0, 1] = 5
