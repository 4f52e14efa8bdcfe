// rFeel: five infrared cones (1 right, 2 front-right, 4 front, 8 front-left, 16 left).
rectangle 380, 100, 420, 110, black, black
rLocate 400, 300
while rFeel() = 0
  rForward 1
wend
print rFeel(), " ", rGPSY() // expect: 4 150
print rBumper() // expect: 0
rTurn -90
print rFeel() // expect: 1
rTurn 180
print rFeel() // expect: 16
