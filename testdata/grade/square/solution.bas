// The teacher's solution: a square of side 120 starting at 400,300 (the seed's Figure 1.7),
// then the perimeter.
rLocate 400,300
rInvisible GREEN
LineWidth 4
rPen DOWN
for n = 1 to 4
  rForward 120
  rTurn 90
next
print "perimeter " + 4 * 120
