// Ada: the route, four drives.
moves = 0
rForward 420
moves = moves + 1
rTurn 90
rForward 220
moves = moves + 1
rTurn 90
rForward 450
moves = moves + 1
rTurn -90
rForward 360
moves = moves + 1
print "reached in " + moves + " moves"
