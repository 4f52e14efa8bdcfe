// Argument counts are checked against the built-in table and the program's subs.
x = abs(1, 2) // expect-error: 'abs()' takes 1 argument, got 2
x = left("a") // expect-error: 'left()' takes 2 arguments, got 1
x = mid("abc") // expect-error: 'mid()' takes 2 to 3 arguments, got 1
x = min(1) // expect-error: 'min()' takes at least 2 arguments, got 1
x = timer(1) // expect-error: 'timer()' takes 0 arguments, got 1
delay // expect-error: 'delay' takes 1 argument, got 0
call Two(1) // expect-error: sub 'Two' takes 2 arguments, got 1
call Ref(5) // expect-error: argument 1 of Ref is passed by reference (&): it must be a variable
end
sub Two(a, b)
return
sub Ref(&r)
  r = 1
return
