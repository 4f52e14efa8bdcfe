' Ben: the prompt is worded his own way; what he prints is right.
input "Number of sides please: ", sides
rLocate 400,300
rInvisible Green
rPen Down
for k = 1 to sides
  rForward 120
  rTurn 90
next
print "sides: " + sides
print "perimeter: " + sides * 120
