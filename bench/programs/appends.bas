// appends: s = s + "x", 100,000 times; prints the length, 100000.
s = ""
for i = 1 to 100000
  s = s + "x"
next
print length(s)
