// Eve: forgot a + in the report line.
n = 0
rForward 420
rTurn 90
rForward 220
rTurn 90
rForward 450
rTurn -90
rForward 360
n = 4
print "reached in " + n " moves"
