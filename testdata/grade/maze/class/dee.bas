// Dee: waits for the robot to find the goal by itself, for ever.
while rBumper() = 0
  rTurn 1
wend
