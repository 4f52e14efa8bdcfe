// Grazing a wall at a shallow angle: the wall enters the robot's disc through its side, which
// presses the side bumper but is no crash; the front bumper fires before the front of the rim
// could touch it, and the robot turns away and drives off.
rectangle 0, 400, 799, 599, black, black
rLocate 60, 375, 92
side = 0
while (rBumper() & 4) = 0
  if rBumper() & 2 then side = 1
  rForward 1
wend
print side // expect: 1
print rGPSY() > 380 // expect: 1
rTurn -150
rForward 100
print rBumper() // expect: 0
