// Figure 1.7 without rInvisible: the pen draws in the current colour (black), an obstacle. The
// trail under the robot is harmless while the robot drives away from it; the square fails on
// its fourth side, where the front of the robot meets the first side's trail (x 398..401).
rLocate 400,300
LineWidth 4
rPen DOWN
for n = 1 to 4
  rForward 120 // expect-runtime-error: robot crashed into an obstacle: its own pen trail (colour Black); add 'rInvisible Black' before 'rPen down' so the robot does not see its trail
  print n, " ", rGPSX(), " ", rGPSY()
  rTurn 90
next
// expect: 1 400 180
// expect: 2 520 180
// expect: 3 520 300
