// Emma: a perfect square, but she forgot to print.
input "How many sides? ", n
rLocate 400, 300
rInvisible GREEN
rPen DOWN
for i = 1 to n
  rForward 120
  rTurn 90
next
