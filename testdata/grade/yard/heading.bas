// Run after the student's program: the robot must end where it started, facing up again.
h = rCompass()
if h <> 0
  print "fail: the robot ends facing " + h + " degrees; turn it back to face up (0 degrees)"
else
  print "the robot ends facing up"
endif
