-- arrays: sieve of Eratosthenes up to 2,000,000; prints the prime count 148933.
-- Lua has no dim: the table is filled with zeros first (indices 0..n).
local n = 2000000
local flags = {}
for i = 0, n do
  flags[i] = 0
end
local count = 0
for i = 2, n do
  if flags[i] == 0 then
    count = count + 1
    for j = i * i, n, i do
      flags[j] = 1
    end
  end
end
print(count)
