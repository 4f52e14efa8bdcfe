// fib: fib(27) by the doubly recursive definition, a sub that returns its value
// (311,809 calls); prints 196418.
print Fib(27)
end

sub Fib(n)
  if n < 2 then return n
  return Fib(n - 1) + Fib(n - 2)
