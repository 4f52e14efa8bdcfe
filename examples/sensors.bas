// Sensors: what the robot can tell about the world around it.
// A few things are drawn around the robot; it reads every sensor, then turns round in steps of
// 45 degrees and says how far away the nearest thing is and what colour it has.

// The world: a red box ahead, a blue post to the right, a green line on the floor under the
// robot, from front to back.
rectangle 330, 60, 470, 120, Red, Red
circle 600, 270, 660, 330, Blue, Blue
setColor Green        // (and the text printed below: green, so the robot does not see it)
lineWidth 6
gotoXY 400, 150
lineTo 400, 450
rInvisible Green      // a floor marking: the robot drives over it and looks through it
rLocate 400, 300

print "bumpers ", rBumper(), ", infrared ", rFeel(), ", floor ", rSense(), " (2: the middle sensor)"
print "compass ", rCompass(), ", at ", rGPSX(), ", ", rGPSY(), ", battery ", rChargeLevel(), "%"
print "the red box is ", rBeacon(Red), " pixels ahead"
print
print "angle"; "range"; "colour"
for angle = 0 to 315 step 45
  c = rLook(angle)
  name = "the screen's edge"
  if c = Red then name = "red"
  if c = Blue then name = "blue"
  print angle; rRange(angle); name
next

// Drive up to the box and feel it.
while (rFeel() & 4) = 0
  rForward 5
wend
print
print "near the box: infrared ", rFeel(), ", range ", rRange(), ", bumpers ", rBumper()
