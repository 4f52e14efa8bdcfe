// instr, contains and replace with needles of 64 characters and more (searched in linear time,
// however the strings repeat): the first match, after partial matches and from a start.
a = ""
for i = 1 to 100
  a = a + "a"
next
n = a + "b"
h = a + a + "b" + a + "b"
print instr(h, n) // expect: 101
print instr(h, n, 102) // expect: 202
print instr(h, n, 203) // expect: 0
print instr(a + a, n) // expect: 0
print contains(h, n) // expect: 1
print length(replace(h, n, "x")) // expect: 102
p = "ab" + a
print instr("aab" + a + "ab" + a, p) // expect: 2
