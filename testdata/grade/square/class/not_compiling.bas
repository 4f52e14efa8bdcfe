// A typo: rForwad is not a command, so nothing runs.
rLocate 400,300
rInvisible GREEN
LineWidth 4
rPen DOWN
for n = 1 to 4
  rForwad 120
  rTurn 90
next
print "perimeter " + 4 * 120
