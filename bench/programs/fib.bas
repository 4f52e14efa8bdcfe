// fib: fib(34) by the doubly recursive definition, a sub that returns its value
// (18,454,929 calls); prints 5702887.
print Fib(34)
end

sub Fib(n)
  if n < 2 then return n
  return Fib(n - 1) + Fib(n - 2)
