// The course labs' random roamer in an empty arena: it drives while the front bumper is free,
// then turns 120 to 180 degrees. 1,000,000 forward steps; run by bench/robot/roamers.sh, one
// seed per run (--seed). A crash stops it with "robot crashed into an obstacle".
rLocate 400, 300
steps = 0
turns = 0
while steps < 1000000 and turns < 1000000
  while (rBumper() & 4) = 0 and steps < 1000000
    rForward 1
    steps++
  wend
  rTurn 120 + random(60)
  turns++
wend
print "steps ", steps, " turns ", turns
