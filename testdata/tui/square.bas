// The seed's Figure 1.7 square, slowed down with rSpeed so that the live view can be watched,
// paused and stepped (tui_test.py drives it in tmux; headless it just runs).
rLocate 400,300
rSpeed 4
rInvisible GREEN
LineWidth 4
rPen DOWN
for n = 1 to 4
  rForward 120
  rTurn 90
next
print "square done"
// expect: square done
