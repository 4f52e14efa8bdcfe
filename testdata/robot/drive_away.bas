// Something drawn over the robot after it was placed: turning never crashes, and the robot
// drives away from it, but not on into it.
rLocate 400, 300
rectangle 405, 270, 430, 330, black, black
print rBumper() // expect: 7
rTurn 270
print rBumper() // expect: 11
rForward 40
print rGPSX() // expect: 360
rForward -18
rForward -10 // expect-runtime-error: robot crashed into an obstacle: colour Black at (405, 300)
