// Output arguments must be variables that can receive a value.
x = 1
call Get(x)
dim r[2]
data Red; 1 // expect-error: cannot use 'Red' as an array: it is a built-in constant (Red: colour 4); use another name, such as 'myRed'
end
sub Get(&v)
  v = 2
return
