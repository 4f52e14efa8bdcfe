// A by-reference argument of a sub called in an expression is copied back, as in a call
// statement: 'filled' is assigned by Fill, so rb check does not call it never assigned.
n = Fill(filled)
print filled // expect: 5
print n // expect: 1
end

sub Fill(&into)
  into = 5
  return 1
endsub
