// Up past the top of the wall, right over it, then into the goal.
rForward 390
rTurn 90
rForward 580
print "goal!"
