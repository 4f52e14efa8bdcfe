-- fib_sub: fib(34) by the doubly recursive definition (18,454,929 calls); prints 5702887.
-- Lua has no by-reference parameters: this is fib.lua, a local function returning its value.
local function fib(n)
  if n < 2 then return n end
  return fib(n - 1) + fib(n - 2)
end
print(fib(34))
