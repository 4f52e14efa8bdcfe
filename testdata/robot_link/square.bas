// The seed's square with a pen (Figure 1.7). link_tests.py traces it on the simulator and on
// the robot emulator (rb trace --real) and compares every event's pose.
rLocate 400,300
rInvisible GREEN
LineWidth 4
rPen DOWN
for n = 1 to 4
  rForward 120
  rTurn 90
next
