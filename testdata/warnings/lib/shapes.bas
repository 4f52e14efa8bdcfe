// nontest: a library included by ../unused.bas; what a program leaves unused is no news
goto ShapesEnd

Square:
  print "square"
return

Triangle:
  print "triangle"
return

sub Ring(r)
  print "ring " + r
endsub

ShapesEnd:
