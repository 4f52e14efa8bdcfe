// roam_status: 100,000 sensed roaming steps among drawn obstacles (the obstacles of roam.bas),
// writing a two-part status line every `every` steps (0: never): xyText with the step and the
// turns so far, xyString with the robot's position. The text is drawn in the arena, so the
// robot senses it like any other obstacle. bench/robot/status.sh runs it for every = 1, 10,
// 100 and 0.
every = 100
rectangle 150, 120, 260, 200, black, black
rectangle 520, 380, 640, 470, blue, blue
circle 300, 350, 380, 430, red, red
circle 600, 100, 680, 180, green, green
rectangle 100, 480, 300, 500, black, black
line 450, 50, 450, 250, 6, black
rLocate 400, 300
turns = 0
for n = 1 to 100000
  if rBumper() & 4
    rTurn 150
    turns++
  elseif rFeel() & 14
    rTurn 30
    turns++
  endif
  rForward 1
  if every > 0
    if n % every = 0
      xyText 20, 560, "step " + n + "  turns " + turns + "   ", "", 10
      xyString 420, 560, "x ", rGPSX(), "  y ", rGPSY(), "   "
    endif
  endif
next
print turns, " ", rGPSX(), " ", rGPSY()
