// and/or evaluate their right side only when needed.
calls = 0
if 0 and Side() then print "no"
print calls // expect: 0
if 1 or Side() then print "or" // expect: or
print calls // expect: 0
if 1 and Side() then print "and" // expect: and
print calls // expect: 1
v = 0 or Side()
print v, calls // expect: 12
end
sub Side()
  _calls = _calls + 1
  return 1
