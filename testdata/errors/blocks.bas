x = 0 // Unmatched block statements: errors where the run would fail.
wend // expect-error: wend without while
next // expect-error: next without for
until x // expect-error: until without repeat
endif // expect-error: endif without if
else // expect-error: else without if
elseif x // expect-error: elseif without if
break // expect-error: break outside a loop
continue // expect-error: continue outside a loop
while 1
  if 1
wend // expect-error: wend closes a while, but the if at line 11 is still open (missing endif)
  endif
wend
for i = 1 to 2
next j // expect-error: next j does not match the for i at line 15
next
if 1
else
else // expect-error: second else for the if at line 18
elseif 1 // expect-error: elseif after else (the if is at line 18)
endif
for i = 1 to 3
endif // expect-error: endif does not match the open for at line 23
next
endsub // expect-error: endsub without a sub
return 5 // expect-error: return with a value outside a sub
for abs = 1 to 2 // expect-error: cannot assign to 'abs': it is a built-in function (abs(x): absolute value); use another name, such as 'myAbs'
next
while 1 // expect-error: while without wend before the end of the file
