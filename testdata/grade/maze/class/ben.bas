// Ben: the route in shorter drives: right, with more moves than it takes.
moves = 0
for i = 1 to 2
  rForward 210
  moves = moves + 1
next
rTurn 90
rForward 220
moves = moves + 1
rTurn 90
for i = 1 to 2
  rForward 225
  moves = moves + 1
next
rTurn -90
rForward 360
moves = moves + 1
print "reached in " + moves + " moves"
