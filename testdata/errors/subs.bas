// Declaration errors of subs.
call A(1, 2)
end
sub A(x, x) // expect-error: parameter 'x' appears twice
return
sub A(y) // expect-error: duplicate sub 'A'
return
sub abs(v) // expect-error: cannot use 'abs' as a sub name: it is a built-in function (abs(x): absolute value); use another name, such as 'myAbs'
return
B: // expect-error: label 'B' has the name of a sub
return
sub B()
return
