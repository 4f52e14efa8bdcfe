// A maze of black walls on a grid of 100 px cells, and a robot that follows the wall on its
// right with its infrared sensors and front bumper (the right-hand rule) for 40,000 rounds.
eRectangle 50, 50, 750, 550, 6, black
for k = 1 to 6
  line 50 + k * 100, 50 + (k % 3) * 100, 50 + k * 100, 350 + (k % 2) * 100, 6, black
next
line 150, 450, 450, 450, 6, black
line 250, 150, 550, 150, 6, black
line 450, 250, 750, 250, 6, black
rLocate 100, 500, 90
while (rBumper() & 4) = 0
  rForward 1
wend
rTurn -90
rounds = 0
moves = 0
while rounds < 40000
  f = rFeel()
  if rBumper() & 4
    rTurn -90
  elseif f & 4
    rTurn -15
  elseif (f & 3) = 0
    rTurn 5
    rForward 2
    moves++
  elseif f & 2
    rTurn -5
    rForward 1
    moves++
  else
    rForward 2
    moves++
  endif
  rounds++
wend
print "moves ", moves, " at ", round(rGPSX()), ", ", round(rGPSY())
