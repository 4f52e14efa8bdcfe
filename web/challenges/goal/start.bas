// The robot stands at the bottom left, facing up. Reach the green goal without bumping
// into the wall, then print "goal!".
rTurn 90
rForward 580
print "goal!"
