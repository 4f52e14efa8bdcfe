// Farid: the sides are a little long.
input "How many sides? ", n
rLocate 400, 300
rInvisible GREEN
rPen DOWN
for i = 1 to n
  rForward 124
  rTurn 90
next
print "sides: " + n
print "perimeter: " + n * 124
