// Robot motion without rSpeed: headless it is instantaneous, the live view shows every step
// (tui_test.py: the pose changes between two looks).
rLocate 400, 300
for s = 1 to 3
  for n = 1 to 4
    rForward 100
    rTurn 90
  next
next
print "three squares"
// expect: three squares
