// A sensor in a loop's condition before the loop places the robot: the first test stops.
rectangle 100, 100, 200, 200
while rRange() > 20 // expect-warning: the robot is not placed yet when 'rRange' runs: rLocate x, y places it // expect-runtime-error: the robot has not been placed: use rLocate x, y first
  rLocate 400, 300
  rForward 10
wend
