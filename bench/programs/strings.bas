// strings: 900,000 iterations of concatenation with numbers, case change, substrings,
// search and length; prints 29477790.
total = 0
for i = 1 to 900000
  s = "item" + i + "-" + (i % 7)
  u = upper(s)
  t = left(u, 3) + mid(s, 5, 3) + lower(right(u, 4))
  total = total + length(t) + length(s) + instr(u, "-")
next
print total
