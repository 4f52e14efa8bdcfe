s = "aaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaa"
for i = 1 to 30
  s = replace(s, "a", "aa") // expect-runtime-error: replace(): string too long
next
