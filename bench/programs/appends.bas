// appends: s = s + "x", 150,000 times; prints the length, 150000.
s = ""
for i = 1 to 150000
  s = s + "x"
next
print length(s)
