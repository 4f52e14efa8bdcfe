// A bumper roamer: the robot drives straight ahead until a bumper touches something, backs up a
// little, turns a random amount and drives on. It stops after 30 bumps.
// Run it again for another path (random numbers differ from run to run).

// Some furniture to bump into.
rectangle 150, 120, 300, 200, Black, Gray
rectangle 520, 380, 640, 520, Black, Gray
circle 480, 100, 580, 200, Black, Brown
circle 160, 400, 260, 500, Black, Brown

rLocate 400, 300
rInvisible LightRed   // the pen's colour: the robot ignores its own trail
lineWidth 2
rPen Down

bumps = 0
driven = 0
while bumps < 30
  // Ahead while the front bumper (4) and the side bumpers (2 right, 8 left) touch nothing.
  while (rBumper() & 14) = 0
    rForward 1
    driven = driven + 1
  wend
  bumps = bumps + 1
  // Back up a little, unless the rear bumper (1) already touches something.
  for i = 1 to 10
    if rBumper() & 1 then break
    rForward -1
  next
  rTurn 90 + random(180)
wend
print "30 bumps, ", driven, " pixels driven"
