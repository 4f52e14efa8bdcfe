// replace() stops at rb's string limit (64 MiB): 1,100 matches, each replaced by 64 KiB.
w = "aaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaa"
for i = 1 to 10
  w = w + w
next
s = left(w, 1100)
s = replace(s, "a", w) // expect-runtime-error: replace(): string too long
