// pen_long: 10,000,000 pen-down moves: a square of side 150 driven 250,000 times round, then
// a spiral of 1,000 squares (rForward/rTurn, the pen down throughout).
rLocate 400, 300
rInvisible GREEN
rPen down
for i = 1 to 2500000
  rForward 150
  rTurn 90
next
for i = 1 to 1000
  rForward 1 + (i % 40)
  rTurn 91
next
print rGPSX(), ",", rGPSY()
