// An element assigned to its own array's variable is copied before the array is released
// (this read freed memory before: the variable printed nothing, or garbage).
dim a[2]
a[0] = "text"
a = a[0]
print a // expect: text
dim n[3]
n[2] = 7
n = n[2] + 1
print n // expect: 8
