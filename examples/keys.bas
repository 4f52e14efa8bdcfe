// Keys: drive the robot from the keyboard.
// Click the screen first, so that it gets your keys. Then:
//   w drives forward, s backs up, a and d turn left and right,
//   p lifts the pen or puts it down, q quits.
// The robot feels with its bumpers before each step, so it stops at a wall instead of crashing.

rLocate 400, 300
rInvisible Blue       // the pen's colour: the robot drives over its own trail
setColor Blue         // and prints in it: text on the screen would be a wall to the robot
lineWidth 3
rPen Down
penIsDown = True
print "w forward, s back, a left, d right, p pen, q quit"

repeat
  waitKey k
  if k = ascii("w") then gosub Forward
  if k = ascii("s") then gosub Back
  if k = ascii("a") then rTurn -15
  if k = ascii("d") then rTurn 15
  if k = ascii("p") then gosub TogglePen
until k = ascii("q")
print "The robot is at ", rGPSX(), ", ", rGPSY(), ", heading ", rCompass()
end

// 20 pixels ahead, one at a time, while the front bumper (4) touches nothing.
Forward:
  for i = 1 to 20
    if rBumper() & 4
      print "Bump! A wall ahead."
      break
    endif
    rForward 1
  next
return

// 20 pixels back, while the rear bumper (1) touches nothing.
Back:
  for i = 1 to 20
    if rBumper() & 1
      print "Bump! A wall behind."
      break
    endif
    rForward -1
  next
return

TogglePen:
  penIsDown = not penIsDown
  rPen penIsDown
return
