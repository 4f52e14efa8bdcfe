// appends1m: s = s + "x", 1,000,000 times; prints the length, 1000000.
s = ""
for i = 1 to 1000000
  s = s + "x"
next
print length(s)
