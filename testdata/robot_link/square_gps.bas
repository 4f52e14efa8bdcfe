// The square again, reading the robot's position and heading after each side. On the
// simulator these are the expectations below; link_tests.py runs it against the robot
// emulator too, where the same numbers must come back over the wire.
rLocate 400,300
for n = 1 to 4
  rForward 120
  rTurn 90
  print rGPSX() + " " + rGPSY() + " " + rCompass()
next
// expect: 400 180 90
// expect: 520 180 180
// expect: 520 300 270
// expect: 400 300 0
