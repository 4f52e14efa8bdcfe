// pen: 100,000 pen-down segments (rForward/rTurn) drawing a growing spiral of squares.
rLocate 400, 300
rInvisible GREEN
rPen down
for i = 1 to 100000
  rForward 1 + (i % 40)
  rTurn 91
next
print rGPSX(), ",", rGPSY()
