rLocate 400, 300, 0, 60 // expect-runtime-error: rLocate: the robot's radius must be between 5 and 50
