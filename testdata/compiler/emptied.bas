// Finishing the code: a call empties only the locals that some path may read before giving
// them a value. Sum writes t before reading it and Twice writes both of its locals first, so
// their calls empty nothing; Pick sets m on one path only and reads it after, so every call
// empties m; in Mixed only s and u may be read first (w and z are written first), so a call
// empties the range s..u.
print Sum(2, 3); Pick(1); Twice(4); Mixed(2) // expect: 5	1	8	7
end

sub Sum(a, b)
  t = a + b
return t

sub Pick(k)
  if k > 0 then m = k
return m

sub Twice(v)
  x = v
  y = x + v
return y

sub Mixed(k)
  w = 1
  if k > 1 then s = k
  if k > 1 then u = 4
  z = s + w + u
return z
