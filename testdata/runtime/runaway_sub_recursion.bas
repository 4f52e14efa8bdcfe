call R(1)
end
sub R(n)
  call R(n + 1) // expect-runtime-error: too many nested gosub/call (100000): runaway recursion?
return
