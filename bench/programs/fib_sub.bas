// fib_sub: fib(34) by the doubly recursive definition, a sub run with `call` that passes its
// result back through a by-reference (&) parameter (18,454,929 calls); prints 5702887.
call Fib(34, r)
print r
end

sub Fib(n, &r)
  if n < 2
    r = n
  else
    call Fib(n - 1, a)
    call Fib(n - 2, b)
    r = a + b
  endif
return
