-- fib_sub: fib(27) by the doubly recursive definition (311,809 calls); prints 196418.
-- Lua has no by-reference parameters: this is fib.lua, a local function returning its value.
local function fib(n)
  if n < 2 then return n end
  return fib(n - 1) + fib(n - 2)
end
print(fib(27))
