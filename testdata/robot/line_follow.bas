// Follow a drawn line with the three floor sensors (4 left, 2 middle, 1 right); the line is
// drawn in an invisible colour, so the robot drives over it.
lineWidth 6
setColor green
gotoXY 100, 500
lineTo 400, 500
lineTo 700, 350
rInvisible GREEN
rLocate 100, 500, 90
print rSense() // expect: 2
steps = 0
while rGPSX() < 690 and steps < 3000
  s = rSense()
  if s = 0 then rTurn -3 // lost it: the line bends left
  if s & 4 then rTurn -2
  if s & 1 then rTurn 2
  rForward 1
  steps++
wend
// On the line's last stretch, y = 500 - (x - 400) / 2.
print abs(rGPSY() - (500 - (rGPSX() - 400) / 2)) < 6 // expect: 1
print steps < 3000 // expect: 1
