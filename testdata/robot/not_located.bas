print rBumper() // expect-warning: the robot is not placed yet when 'rBumper' runs: rLocate x, y places it // expect-runtime-error: the robot has not been placed: use rLocate x, y first
