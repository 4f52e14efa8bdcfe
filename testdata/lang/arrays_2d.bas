// Two-dimensional arrays (the IndexGet2/IndexSet2 fast path and its fallbacks): row-major
// elements in a non-square array, converted indices, strings shared with copies, compound
// assignment, an element read into the array's own variable, and arrays in subs.
dim m[3, 5]
for i = 0 to 2
  for j = 0 to 4
    m[i, j] = 10 * i + j
  next
next
s = 0
for i = 0 to 2
  for j = 0 to 4
    s = s + m[i, j] * (i + 1) * (j + 7)
  next
next
print s // expect: 4200
print m[2, 4], " ", m[1, 0], " ", m[0, 4] // expect: 24 10 4
// Double indices are truncated toward zero; indices may be any expression.
print m[1.9, 2.2] // expect: 12
k = 1
print m[k + 1, k * 3] // expect: 23
// Strings: a copy read from an element keeps its text when the element changes.
m[0, 0] = "first"
t = "old"
t = m[0, 0]
m[0, 0] = m[0, 0] + " changed"
print t // expect: first
print m[0, 0] // expect: first changed
// Compound assignment reads and writes the same element.
m[1, 2] += 5
m[1, 2]++
print m[1, 2] // expect: 18
// Reading an element into the array's own variable replaces the array by the element.
dim q[2, 2]
q[1, 1] = "kept"
q = q[1, 1]
print q // expect: kept
// A 2-D array in a sub is the global array; passed as an argument it is the same array.
call Fill(3)
print m[2, 3] // expect: 3
call Put(m, 2, 2)
print m[2, 2] // expect: 99
print Get(m, 2, 2) // expect: 99
// A new dim replaces the array: the new extents apply.
dim m[2, 2]
print m[1, 1] // expect: 0
// Three and more indices take the general path.
dim c[2, 3, 4]
c[1, 2, 3] = 7
print c[1, 2, 3] + c[0, 0, 0] // expect: 7
end

sub Fill(v)
  m[2, 3] = v
return

sub Put(arr, i, j)
  arr[i, j] = 99
return

sub Get(arr, i, j)
  return arr[i, j]
