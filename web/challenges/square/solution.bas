rLocate 400,300
rInvisible GREEN
LineWidth 4
rPen DOWN
for n = 1 to 4
  rForward 120
  rTurn 90
next
