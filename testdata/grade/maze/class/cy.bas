// Cy: the route, then on through the lava and out of the goal.
moves = 0
rForward 420
rTurn 90
rForward 220
rTurn 90
rForward 450
rTurn -90
rForward 360
rTurn -90
rForward 280
moves = 5
print "reached in " + moves + " moves"
