// rb check warns about a goto or gosub to a label inside a sub, from outside that sub: the
// code there runs with none of the sub's variables.
gosub Inside // expect-warning: label 'Inside' is inside sub 'Draw': a gosub from outside the sub runs its code without the sub's variables; call the sub, or move the label out of it
// expect: inside
call Draw(5) // expect: 5
// expect: inside
call Other()
print "done" // expect: done
end

sub Draw(size)
  print size
Inside:
  print "inside"
endsub

sub Other()
  if 0 then goto Inside // expect-warning: label 'Inside' is inside sub 'Draw': a goto from outside the sub runs its code without the sub's variables; call the sub, or move the label out of it
  gosub Routine // a label of the main program: no warning
  goto Here // a label of its own: no warning
  print "skipped"
Here:
endsub

Routine:
return
