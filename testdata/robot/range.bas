// rRange: distance from the robot's edge to the first obstacle along heading + angle.
line 600, 0, 600, 599
rLocate 400, 300
print rRange(90) // expect: 180
print rRange() // expect: 281
print rRange(-90) // expect: 381
while rRange(90) > 20
  rTurn 90
  rForward 10
  rTurn -90
wend
print rGPSX() // expect: 560
