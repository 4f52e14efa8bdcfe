// Locals of a sub start without a value on every call.
call F()
end
sub F()
  print v // expect-runtime-error: variable 'v' is used before it is given a value // expect-warning: variable 'v' is read but never assigned in this sub
return
