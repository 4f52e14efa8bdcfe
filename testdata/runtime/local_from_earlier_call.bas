// A local that the sub gives a value on one path only is empty at every call, whatever an
// earlier call left in its slot: the second call of Pick reads m before giving it a value.
print Pick(3) // expect: 3
print Pick(0)
end

sub Pick(k)
  if k > 0 then m = k
return m + 0 // expect-runtime-error: variable 'm' is used before it is given a value
