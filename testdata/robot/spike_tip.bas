// A robot edging around a spike's tip can still hit it: the thin tip slips between the
// infrared cones (front is +-10 degrees, front-right 35..55), so a robot that watches only its
// front sensor drives into it. Its front bumper would have told it two steps before.
line 400, 300, 650, 292, 1, black
line 400, 300, 650, 308, 1, black
line 650, 292, 650, 308, 1, black
floodFill 600, 300, black
// Following the spike's lower edge leftward, the spike on the right, until the tip is passed.
rLocate 560, 327, 270
while rFeel() & 1
  rForward 1
wend
print rGPSX(), " ", rGPSY() // expect: 395 327
// Turning round the tip never crashes, however close it is.
rTurn 90
while (rFeel() & 4) = 0
  b = rBumper()
  rForward 1 // expect-runtime-error: robot crashed into an obstacle: colour Black at (400, 300)
  print rGPSY(), " ", b
wend
// expect: 326 0
// expect: 325 0
// expect: 324 0
// expect: 323 0
// expect: 322 0
// expect: 321 0
// expect: 320 4
