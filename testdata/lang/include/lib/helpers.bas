// nontest: included by ../main.bas
goto SkipHelpers

Greet:
  print "hello from the library"
return

sub Twice(n)
  return n * 2
endsub

SkipHelpers:
