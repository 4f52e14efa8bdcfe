// Jade: sides of 200 reach the flower bed.
input "How many sides? ", n
rLocate 400, 300
rInvisible GREEN
rPen DOWN
for i = 1 to n
  rForward 200
  rTurn 90
next
print "sides: " + n
print "perimeter: " + n * 200
