// rb check warns about a sub nothing calls, and about a label nothing jumps to when the code
// before it never goes on to it: the code after it never runs. Only for this file: the
// library it includes offers more than the program uses.
#include "lib/shapes.bas"
Main: // a marker the code runs into: no warning
  gosub Square // expect: square
  call Used(1) // expect: 1
  n = Twice(2)
  print n // expect: 4
  call Jumper()
end

Forgotten: // expect-warning: label 'Forgotten' is never used: no goto or gosub jumps to it, so the code after it never runs
  print "never"
return

sub Used(a)
  print a
endsub

sub Twice(v) // used in an expression
  return Helper(v) * 2
endsub

sub Helper(v) // called by another sub
  return v
endsub

sub Spare(x) // expect-warning: sub 'Spare' is never called
  if x > 0 then call Spare(x - 1) // calls from its own body do not count
endsub

sub Jumper()
  goto FromSub // a label used only from a sub is used
endsub
FromSub:
return
