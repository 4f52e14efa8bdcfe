// rb check warns about a robot statement or sensor that every way to it reaches before
// rLocate; the simulator stops there. Only the first one on a way is reported: the program
// has stopped before the others.
print "start" // expect: start
rPen down // rPen, rSpeed, rInvisible and rSlip need no placed robot
rSpeed 0
rInvisible Green
rSlip 0
if rChargeLevel() < 0 then rTurn 90 // expect-warning: the robot is not placed yet when 'rTurn' runs: rLocate x, y places it
gosub Look
rForward 10
rLocate 400, 300
end

Look:
  if rFeel() = 0 // expect-warning: the robot is not placed yet when 'rFeel' runs: rLocate x, y places it // expect-runtime-error: the robot has not been placed: use rLocate x, y first
    rTurn 90
  endif
return
