// Text is drawn with a real font into the screen, so the robot senses it like any drawing.
xyText 360, 150, "WALL", "", 24, "b", black
rLocate 400, 300
print rRange() < 140 // expect: 1
print rLook() // expect: 0
