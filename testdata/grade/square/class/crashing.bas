// The first side is far too long: the robot drives into the top of the screen.
rLocate 400,300
rInvisible GREEN
LineWidth 4
rPen DOWN
rForward 400
rTurn 90
rForward 120
print "perimeter " + 4 * 120
