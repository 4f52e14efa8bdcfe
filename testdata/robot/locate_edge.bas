// rLocate where the robot would stick out of the screen puts it just inside, touching the edge
// (a published program does rLocate 110,600; RobotBASIC shows the robot at about 110,580).
rLocate 110, 600
print rGPSX(), " ", rGPSY() // expect: 110 579
print rBumper() // expect: 1
rLocate -40, 300, 90, 10
print rGPSX(), " ", rGPSY() // expect: 10 300
rLocate 900, -5, 0, 50
print rGPSX(), " ", rGPSY() // expect: 749 50
rForward -100
print rGPSY() // expect: 150
// Over a drawn obstacle it stays an error.
rectangle 0, 560, 200, 599, black, black
rLocate 110, 600 // expect-runtime-error: rLocate: the robot at (110, 600) would overlap an obstacle
