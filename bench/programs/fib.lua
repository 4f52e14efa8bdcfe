-- fib: fib(34) by the doubly recursive definition, a local function (18,454,929 calls);
-- prints 5702887.
local function fib(n)
  if n < 2 then return n end
  return fib(n - 1) + fib(n - 2)
end
print(fib(34))
