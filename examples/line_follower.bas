// A line follower: the robot follows a track drawn on the floor with its three floor sensors
// (rSense: 4 left, 2 middle, 1 right) and stops when it is back where it started.

// The track: an oval line in gray, a colour the robot drives over (rInvisible).
lineWidth 12
circle 100, 100, 700, 500, Gray
rInvisible Gray
rLocate 400, 100, 90  // on the track, at its top, heading right (clockwise round the oval)

steps = 0
repeat
  s = rSense()
  if s = 2
    rForward 2        // only the middle sensor sees the line: straight on
  else
    if s & 4 then rTurn -4  // the line is to the left
    if s & 1 then rTurn 4   // the line is to the right
    if s = 0 then rTurn 4   // lost it: the track bends right, so look right
    if s & 2 then rForward 1
  endif
  steps = steps + 1
until (steps > 100 and abs(rGPSX() - 400) < 3 and rGPSY() < 120) or steps = 5000
print "Back at the start after ", steps, " steps"
