// Random roaming over walls drawn with the mouse, in the style of lab 4's randomRoaming: hold the
// left button and drag to draw, right-click to finish; then the robot roams, turning away
// whenever a bumper touches a wall. The roaming is bounded by a count of turns.
// args: --seed 7 --events roaming_walls.events
print "Drag with the left button to draw walls; right-click when done."
waitKey "Press any key to start.", key
clearScr
rLocate 400, 300
setColor Black
lineWidth 4
walls = 0
while true
  repeat
    readMouse x, y, b
  until b = 1 or b = 2
  if b = 2 then break
  gotoXY x, y
  while b = 1
    readMouse x, y, b
    lineTo x, y
  wend
  walls = walls + 1
wend
print "walls drawn: ", walls, "; wall pixel colour ", pixelClr(400, 150), "; outside ", pixelClr(400, 100)
turns = 0
moved = 0
while turns < 25
  while (rBumper() & 14) = 0
    rForward 1
    moved = moved + 1
  wend
  rTurn 120 + random(60)
  turns = turns + 1
wend
inside = within(rGpsX(), 210, 590) and within(rGpsY(), 160, 440)
print "turns ", turns, ", inside the walls: ", inside, ", moved more than 1000: ", moved > 1000
// expect: Drag with the left button to draw walls; right-click when done.
// expect: Press any key to start.walls drawn: 2; wall pixel colour 0; outside 15
// expect: turns 25, inside the walls: 1, moved more than 1000: 1
