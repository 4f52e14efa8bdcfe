// sub/call: parameters and locals, & by reference, _global access, return values.
x = 10
total = 0
counter = 0
call Show(5)
// expect: 5 10
print x // expect: 10
call AddTo(total, 7)
call AddTo(total, 8)
print total // expect: 15
call Bump()
call Bump()
print counter // expect: 2
print Square(12) // expect: 144
print Fact(10) // expect: 3628800
call Out(r)
print r // expect: out
Show(1)
// expect: 1 2
dim arr[3]
call Fill(arr)
print arr[0], arr[2] // expect: 714
end

sub Show(x)
  y = x * 2
  print x, " ", y
return

sub AddTo(&acc, n)
  acc = acc + n
return

sub Bump()
  _counter = _counter + 1
endsub

sub Square(v)
  return v * v

sub Fact(n)
  if n <= 1 then return 1
  return n * Fact(n - 1)

sub Out(&result)
  result = "out"
return

sub Fill(a)
  a[0] = 7
  a[2] = 14
return
