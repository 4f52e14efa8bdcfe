// Drive until the front bumper touches a wall drawn ahead, then check the bits on each side.
rectangle 300, 100, 500, 120, black, black
rLocate 400, 300
while (rBumper() & 4) = 0
  rForward 1
wend
print rGPSY() // expect: 142
print rBumper() // expect: 4
rTurn 90
print rBumper() // expect: 8
rTurn 90
print rBumper() // expect: 1
rTurn 90
print rBumper() // expect: 2
