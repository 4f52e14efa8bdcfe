// Labels are addresses: goto/gosub may jump into and out of blocks; end stops the program.
Main:
  k = 0
  gosub Twice
  gosub Twice
  print k // expect: 4
  goto Skip
  print "skipped"
Skip:
  for i = 1 to 10
    if i = 3 then goto Out
  next
Out:
  print i // expect: 3
  n = 0
Again:
  n = n + 1
  if n < 5 then goto Again
  print n // expect: 5
  gosub Nested
  goto Finish

Twice:
  if k = 0 then k = 1
  k = k * 2
return

Inner:
  print "inner" // expect: inner
  if 1 then return
  print "not reached"
return

Nested:
  gosub Inner
  print "back" // expect: back
return

Finish:
  print "done" // expect: done
end
print "after end"
