// dim gives indices 0..n-1, any number of dimensions, elements start at 0; data appends.
dim a[5]
print a[0], a[4] // expect: 00
for i = 0 to 4
  a[i] = i * i
next
print a[3] // expect: 9
dim grid[3, 4]
grid[2, 3] = "corner"
print grid[2, 3] // expect: corner
dim cube[2, 2, 2]
cube[1, 1, 1] = 8
print cube[1, 1, 1] + cube[0, 0, 0] // expect: 8
data primes; 2, 3, 5
data primes; 7, 11
print primes[4] // expect: 11
a[1] += 5
a[1]++
print a[1] // expect: 7
dim b[2], c[3]
c[2] = 1
print b[1] + c[2] // expect: 1
print a[2.9] // expect: 4
dim a[2]
print a[1] // expect: 0
