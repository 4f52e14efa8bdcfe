// Arrays: dim takes its extents in consecutive slots, data appends, a single index is used in
// place, several go to temporaries; a compound assignment to an element reads it, then writes.
dim m[2, 3]
data d; 4, 5
m[1, 2] = 6
m[1, 2] += d[1]
d[0]++
print m[1, 2]; d[0] // expect: 11	5
