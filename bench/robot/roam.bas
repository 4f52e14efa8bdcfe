// roam: a headless robot roams among drawn obstacles for 1,000,000 sensed steps: each step is
// rForward 1 plus rBumper() and rFeel(); a bumper or feel hit turns it away.
rectangle 150, 120, 260, 200, black, black
rectangle 520, 380, 640, 470, blue, blue
circle 300, 350, 380, 430, red, red
circle 600, 100, 680, 180, green, green
rectangle 100, 480, 300, 500, black, black
line 450, 50, 450, 250, 6, black
rLocate 400, 300
turns = 0
for n = 1 to 1000000
  if rBumper() & 4
    rTurn 150
    turns++
  elseif rFeel() & 14
    rTurn 30
    turns++
  endif
  rForward 1
next
print turns
