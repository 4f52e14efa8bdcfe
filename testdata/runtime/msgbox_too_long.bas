// MsgBox joins an array's lines into one text, one string at most (64 MiB): the elements of an
// array may all share one long string, and their lines would make a text without bound.
s = spaces(10000000)
dim a[8]
for i = 0 to 7
  a[i] = s
next
MsgBox a // expect-runtime-error: MsgBox: the array's lines make a text longer than 67108864 characters
