// Arrays: dim takes its extents in consecutive slots, data appends, a single index is used in
// place, two indices into a global array too (IndexGet2/IndexSet2), three or more go to
// temporaries; a compound assignment to an element reads it, then writes.
dim m[2, 3]
data d; 4, 5
m[1, 2] = 6
m[1, 2] += d[1]
d[0]++
print m[1, 2]; d[0] // expect: 11	5
dim c[2, 2, 2]
c[1, 1, 1] = m[1, 2]
print c[1, 1, 1] // expect: 11
