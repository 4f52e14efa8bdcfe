// planner_status: a stand-in for a published path planner (not in this tree) that prints its
// distance to the goal as it drives: on each of three maps the robot heads for the goal,
// follows an obstacle's edge (keeping it on its right) while the way to the goal is blocked, and writes the distance to the
// goal with xyText at every step, in the arena, where the robot senses it like any obstacle.
// Prints, for each map, whether the goal was reached and in how many steps (at most 20,000).
// bench/robot/status.sh runs it as it is and with status = 0 (no status line).
status = 1
gx = 740
gy = 80
for map = 1 to 3
  clearScr
  gosub DrawMap
  circle gx - 6, gy - 6, gx + 6, gy + 6, green, green
  rLocate 60, 540, 0
  steps = 0
  reached = 0
  while steps < 20000 and reached = 0
    x = rGPSX()
    y = rGPSY()
    d = sqrt((gx - x) * (gx - x) + (gy - y) * (gy - y))
    if status then xyText 560, 570, "map " + map + "  to goal " + round(d) + "    ", "", 10, 0, black, white
    if d < 30
      reached = 1
    else
      want = rtod(atan2(gx - x, y - gy))
      turn = want - rCompass()
      while turn > 180
        turn = turn - 360
      wend
      while turn < -180
        turn = turn + 360
      wend
      if rBumper() & 4
        rTurn -90
      elseif rFeel() & 14
        rTurn -10
      elseif rRange(turn) > 40
        if turn > 8 then turn = 8
        if turn < -8 then turn = -8
        rTurn turn
      elseif (rFeel() & 3) = 0
        rTurn 5
      endif
      rForward 1
      steps++
    endif
  wend
  print "map ", map, ": reached ", reached, " in ", steps, " steps"
next
end

DrawMap:
  if map = 1
    rectangle 200, 250, 420, 330, black, black
    rectangle 500, 120, 560, 420, blue, blue
  elseif map = 2
    circle 150, 150, 330, 330, red, red
    circle 380, 300, 520, 440, red, red
    rectangle 560, 140, 600, 520, black, black
  else
    for k = 0 to 5
      rectangle 110 + k * 110, 100 + (k % 2) * 200, 150 + k * 110, 300 + (k % 2) * 200, black, black
    next
  endif
return
