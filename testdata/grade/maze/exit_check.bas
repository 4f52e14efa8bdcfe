// A hidden check, run on the final state: the robot must face the exit (east). It also paints
// a magenta square in a corner, so a test can see that what a post program draws never reaches
// a student's picture.
Rectangle 780, 0, 800, 20, MAGENTA, MAGENTA
if rCompass() <> 90
  print "fail: the robot does not face the exit (east), it faces " + rCompass()
else
  print "ok"
endif
