// matmul: C = A * B for 300 x 300 integer matrices held in two-dimensional arrays
// (dim a[300, 300]); prints the sum of C's elements, 546750000.
n = 300
dim a[n, n], b[n, n], c[n, n]
for i = 0 to n - 1
  for j = 0 to n - 1
    a[i, j] = (i + 2 * j) % 10
    b[i, j] = (3 * i + j) % 10
  next
next
for i = 0 to n - 1
  for j = 0 to n - 1
    s = 0
    for k = 0 to n - 1
      s = s + a[i, k] * b[k, j]
    next
    c[i, j] = s
  next
next
total = 0
for i = 0 to n - 1
  for j = 0 to n - 1
    total = total + c[i, j]
  next
next
print total
