// Ask how many sides, then draw the polygon: 120 px a side, clockwise from (400, 300) facing
// up, back to the start; print the sides and the perimeter.
input "How many sides? ", n
rLocate 400, 300
rInvisible GREEN
LineWidth 4
rPen DOWN
for i = 1 to n
  rForward 120
  rTurn 360 / n
next
print "sides: " + n
print "perimeter: " + n * 120
