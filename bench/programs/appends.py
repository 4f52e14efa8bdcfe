# appends: s = s + "x", 100,000 times; prints the length, 100000.
s = ""
for i in range(100000):
    s = s + "x"
print(len(s))
