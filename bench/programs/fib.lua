-- fib: fib(27) by the doubly recursive definition, a local function (311,809 calls);
-- prints 196418.
local function fib(n)
  if n < 2 then return n end
  return fib(n - 1) + fib(n - 2)
end
print(fib(27))
