// The labs' snippet: drive until a bumper touches; the screen's top edge stops the robot with
// its front bumper 1 or 2 pixels from the wall (the bumper reaches 2 pixels past the rim).
rLocate 400, 300
while rBumper() = 0
   rForward 1
wend
print rBumper() & 4 // expect: 4
y = rGPSY()
print y >= 20 and y <= 24 // expect: 1
print rGPSX() // expect: 400
