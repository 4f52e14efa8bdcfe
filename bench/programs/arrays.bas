// arrays: 6 rounds of the sieve of Eratosthenes up to 2,000,000 (the flags cleared each
// round); prints the prime count 148933.
n = 2000000
dim flags[n + 1]
for r = 1 to 6
  for i = 0 to n
    flags[i] = 0
  next
  count = 0
  for i = 2 to n
    if flags[i] = 0
      count = count + 1
      for j = i * i to n step i
        flags[j] = 1
      next
    endif
  next
next
print count
