// Dev: the right square, drawn the other way round (counter-clockwise).
input "How many sides? ", n
rLocate 400, 300
rInvisible GREEN
LineWidth 4
rPen DOWN
rTurn 90
for i = 1 to n
  rForward 120
  rTurn -90
next
print "sides: " + n
print "perimeter: " + n * 120
