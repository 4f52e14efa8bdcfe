// The course labs' random roamer among drawn rectangles and circles: it drives while the front
// bumper is free, then turns 120 to 180 degrees. 1,000,000 forward steps; run by
// bench/robot/roamers.sh, one seed per run (--seed).
rectangle 150, 120, 260, 200, black, black
rectangle 520, 380, 640, 470, blue, blue
rectangle 100, 480, 300, 500, black, black
rectangle 440, 40, 456, 250, black, black
circle 300, 350, 380, 430, red, red
circle 600, 100, 680, 180, green, green
circle 690, 300, 740, 350, black, black
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
