// s = s + x appends in place only when nothing else holds s: copies, array elements and
// arguments keep their own text.
s = "ab"
t = s
s = s + "c"
print t // expect: ab
print s // expect: abc
s = s + s
print s // expect: abcabc
dim a[2]
a[0] = s
s = s + "!"
print a[0] // expect: abcabc
print s // expect: abcabc!
s = s + 5
print s // expect: abcabc!5
n = 7
n = n + "x"
print n // expect: 7x
call grow(s) // expect: abcabc!5-sub
print s // expect: abcabc!5
u = s
call growRef(s) // expect: abcabc!5
print s // expect: abcabc!5+ref
print u // expect: abcabc!5
dim g[2, 2]
g[1, 1] = s
s = s + "?"
print g[1, 1] // expect: abcabc!5+ref
end

sub grow(v)
  v = v + "-sub"
  print v
return

// A by-reference argument shares its text with the caller's variable until the sub returns:
// the append copies, and only the final value comes back.
sub growRef(&v)
  v = v + "+ref"
  print _u
return
