// Sensors need a placed robot; rLocate checks the radius and the place.
rectangle 0, 0, 100, 100, black, black
rLocate 400, 300, 45, 30, red
print rCompass(), " ", rGPSX() // expect: 45 400
rLocate 50, 50 // expect-runtime-error: rLocate: the robot at (50, 50) would overlap an obstacle
