// Chloe: draws the square, but checks the first side by driving it twice.
input "How many sides? ", n
rLocate 400, 300
rInvisible GREEN
rPen DOWN
rForward 120
rForward -120
rForward 120
rTurn 90
for i = 2 to n
  rForward 120
  rTurn 90
next
print "sides: " + n
print "perimeter: " + n * 120
