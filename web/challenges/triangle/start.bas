// Draw a triangle with three sides of 120 pixels, clockwise, from 400, 300.
rLocate 400,300
rPen DOWN
for n = 1 to 4
  rForward 120
  rTurn 90
next
