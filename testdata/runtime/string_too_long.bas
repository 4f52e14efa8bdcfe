// Strings cannot grow without bound: doubling one ends with an error, not a crash.
s = "0123456789abcdef"
for i = 1 to 40
  s = s + s // expect-runtime-error: string too long (more than 67108864 characters)
next
