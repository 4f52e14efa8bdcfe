// arrays: sieve of Eratosthenes up to 2,000,000; prints the prime count 148933.
n = 2000000
dim flags[n + 1]
count = 0
for i = 2 to n
  if flags[i] = 0
    count = count + 1
    for j = i * i to n step i
      flags[j] = 1
    next
  endif
next
print count
