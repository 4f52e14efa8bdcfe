// Ivan: forgot to place the robot.
input "How many sides? ", n
rPen DOWN
for i = 1 to n
  rForward 120
  rTurn 90
next
print "sides: " + n
print "perimeter: " + n * 120
