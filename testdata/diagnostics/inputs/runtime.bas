// nontest: a runtime error two calls deep (diagnostics/run.t)
Real = 2
gosub Outer
end
Outer:
  call Inner(1)
return
sub Inner(n)
  print n / (real - 2)
return
