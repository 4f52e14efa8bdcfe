// appends10m: s = s + "x", 10,000,000 times; prints the length, 10000000.
s = ""
for i = 1 to 10000000
  s = s + "x"
next
print length(s)
