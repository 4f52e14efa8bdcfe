// Arrays of a million elements and more live in large memory (mapped at once, in huge pages
// where Linux gives them): they start at zero, keep what is written anywhere in them, are shared
// by a sub, are made again by a second dim, and grow past a mebibyte one data item at a time.
dim big[1000000]
big[0] = 1
big[999999] = 2
big[500000] = "middle"
print big[0]; big[999999]; big[500000]; big[123456] = 0 // expect: 1	2	middle	1
call Fill(big, 3)
print big[999998] // expect: 3
dim big[2, 600000]
big[1, 599999] = 4
print big[1, 599999]; big[0, 0] = 0 // expect: 4	1
for i = 1 to 100000
  data grown, i
next
print grown[0]; grown[99999] // expect: 1	100000
end

sub Fill(a, v)
  for i = 999990 to 999998
    a[i] = v
  next
return
