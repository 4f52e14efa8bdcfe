print rBumper() // expect-runtime-error: the robot has not been placed: use rLocate x, y first
