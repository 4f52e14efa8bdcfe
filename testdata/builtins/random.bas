// random(n) gives 0..n-1; randomize restarts the sequence; --seed makes runs repeatable.
// args: --seed 7
ok = 1
for i = 1 to 1000
  r = random(6)
  if r < 0 or r > 5 or r <> int(r) then ok = 0
next
print ok // expect: 1
randomize 42
a = random(1000000)
b = rRandom(1)
randomize 42
print a = random(1000000), b = rRandom(1) // expect: 11
print rRandom(1) < 1 // expect: 1
