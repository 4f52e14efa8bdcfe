// Mouse control in the style of lab 3's mouseControl: a left click drives the robot to the
// clicked point (it stops early when its front bumper touches an obstacle), a right click
// toggles the pen. Like the lab program it polls the mouse forever, so the run ends when the
// script is exhausted and the program has polled for 60 s of virtual time without input.
// args: --events mouse_control.events
mainProgram:
  gosub drawObstacles
  rLocate 600, 80
  rInvisible Green
  gosub remoteControl
end

drawObstacles:
  rectangle 300, 300, 500, 500, Red, Red
  circle 100, 100, 200, 200, Blue, Blue
return

remoteControl:
  p = Up
  repeat
    readMouse x, y, b // expect-runtime-error: readMouse: no more scripted input (the --events script is exhausted, and the program kept polling for 60 s of virtual time)
    if b = 1 then gosub goToPoint
    if b = 2
      p = not p
      rPen p
      print "pen ", p
      delay 200
    endif
  until false
return

goToPoint:
  dx = x - rGpsX()
  dy = y - rGpsY()
  if dx = 0 and dy = 0 then return
  theta = polarA(dx, dy) * 180 / pi() + 90 - rCompass()
  if theta > 180 then theta = theta - 360
  if theta < -180 then theta = theta + 360
  rTurn theta
  distance = round(polarR(dx, dy))
  for i = 1 to distance
    if rBumper() & 4 then break
    rForward 1
  next
  print "click ", x, ",", y, " -> robot at ", rGpsX(), ",", rGpsY()
return
// expect: pen 1
// expect: click 700,200 -> robot at 700,200
// expect: click 700,400 -> robot at 699,400
// expect: click 200,400 -> robot at 521,399
// expect: pen 0
// expect: click 600,150 -> robot at 601,151
