// nontest: rb check's messages, each kind once (diagnostics/check.t)
x = (1 + 2
print x
rForwrd 120
y = abs(1, 2, 3)
z = left("a")
rLocate 1, 2, 3, 4, 5, 6, 7
goto nowher
nowhere:
Total = 5
print total
call Two(1, 2, 3)
if y > 1
  print y
end
sub Two(a, b)
return
