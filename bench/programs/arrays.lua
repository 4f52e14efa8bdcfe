-- arrays: 6 rounds of the sieve of Eratosthenes up to 2,000,000 (the flags cleared each
-- round); prints the prime count 148933. Lua has no dim: the table is filled with zeros
-- (indices 0..n) at the start of each round.
local n = 2000000
local flags = {}
local count
for r = 1, 6 do
  for i = 0, n do
    flags[i] = 0
  end
  count = 0
  for i = 2, n do
    if flags[i] == 0 then
      count = count + 1
      for j = i * i, n, i do
        flags[j] = 1
      end
    end
  end
end
print(count)
