// The loop never ends: the robot goes round the square forever.
rLocate 400,300
rInvisible GREEN
LineWidth 4
rPen DOWN
while 1
  rForward 120
  rTurn 90
wend
print "perimeter " + 4 * 120
